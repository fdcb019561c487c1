namespace Machina.Simulation.Krl;

/// <summary>
/// KRL's reserved words: they cannot name a variable or a routine. STEP is not among them: it is a word of FOR only, and
/// published programs name variables and structure components step.
/// </summary>
internal static class KrlKeywords
{
    private static readonly HashSet<string> Reserved = new(StringComparer.OrdinalIgnoreCase)
    {
        "DEF", "END", "DEFFCT", "ENDFCT", "DEFDAT", "ENDDAT", "IF", "THEN", "ELSE", "ENDIF", "WHILE", "ENDWHILE", "REPEAT", "UNTIL",
        "FOR", "TO", "ENDFOR", "LOOP", "ENDLOOP", "SWITCH", "CASE", "DEFAULT", "ENDSWITCH", "WAIT", "SEC", "EXIT", "HALT",
        "RETURN", "CONTINUE", "GOTO", "INTERRUPT", "DECL", "WHEN", "DO", "ON", "OFF", "ENABLE", "DISABLE", "PTP", "LIN", "CIRC",
        "PTP_REL", "LIN_REL", "CIRC_REL", "AND", "OR", "NOT", "EXOR", "B_AND", "B_OR", "B_NOT", "B_EXOR", "TRUE", "FALSE", "GLOBAL",
        "PUBLIC", "CONST", "SIGNAL", "STRUC", "ENUM", "C_PTP", "C_DIS", "C_ORI", "C_VEL", "TRIGGER", "BRAKE", "RESUME", "ANIN", "ANOUT",
    };

    /// <summary>True when <paramref name="word"/> is reserved.</summary>
    public static bool IsReserved(string word) => Reserved.Contains(word);
}

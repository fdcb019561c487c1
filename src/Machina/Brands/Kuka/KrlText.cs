using System.Text;

namespace Machina;

/// <summary>Makes user text safe for KRL: names that the controller accepts and comments that cannot end early.</summary>
internal static class KrlText
{
    /// <summary>Longest name KRL accepts for modules, variables and signals.</summary>
    internal const int MaxNameLength = 24;

    // Words KRL reserves; a module or signal with one of these names would not compile.
    private static readonly HashSet<string> Keywords = new(StringComparer.OrdinalIgnoreCase)
    {
        "AND", "ANIN", "ANOUT", "AXIS", "B_AND", "B_EXOR", "B_NOT", "B_OR", "BOOL", "BRAKE", "C_DIS", "C_ORI", "C_PTP", "C_VEL",
        "CA", "CASE", "CHAR", "CIRC", "CIRC_REL", "CONST", "CONST_VEL", "CONTINUE", "DECL", "DEF", "DEFAULT", "DEFDAT", "DEFFCT",
        "DELAY", "DISTANCE", "DO", "E6AXIS", "E6POS", "ELSE", "END", "ENDDAT", "ENDFCT", "ENDFOR", "ENDIF", "ENDLOOP", "ENDSPLINE",
        "ENDSWITCH", "ENDWHILE", "ENUM", "EXIT", "EXOR", "EXT", "EXTFCT", "FALSE", "FOR", "FRAME", "GLOBAL", "GOTO", "HALT", "IF",
        "IMPORT", "INT", "INTERRUPT", "IS", "LIN", "LIN_REL", "LOOP", "MAXIMUM", "MINIMUM", "NOT", "OR", "POS", "PRIO", "PTP",
        "PTP_REL", "PUBLIC", "REAL", "REPEAT", "RESUME", "RETURN", "SCIRC", "SEC", "SIGNAL", "SLIN", "SPLINE", "SPTP", "STEP",
        "STRUC", "SWITCH", "THEN", "TIME_BLOCK", "TO", "TRIGGER", "TRUE", "UNTIL", "WAIT", "WHEN", "WHILE",
    };

    /// <summary>True when <paramref name="name"/> can be used as a KRL name: a letter or '_' first, then letters, digits or '_', at most 24 characters, not a keyword.</summary>
    internal static bool IsValidName(string name)
    {
        if (name.Length == 0 || name.Length > MaxNameLength || char.IsAsciiDigit(name[0]))
        {
            return false;
        }
        foreach (char c in name)
        {
            if (!(char.IsAsciiLetterOrDigit(c) || c == '_'))
            {
                return false;
            }
        }
        return !Keywords.Contains(name);
    }

    /// <summary>
    /// The module name for a program: the safe program name, prefixed with "M_" when it is a KRL keyword or a name this compiler
    /// declares or calls itself (<c>target«digits»</c>, the acceleration variable, <c>BAS</c>, <c>IR_STOPM</c>), and cut to 24 characters.
    /// The module (DEF) name and the file name must be the same in KRL.
    /// </summary>
    internal static string ModuleName(string programName)
    {
        var sb = new StringBuilder(programName.Length + 2);
        foreach (char c in programName)
        {
            sb.Append(char.IsAsciiLetterOrDigit(c) || c == '_' ? c : '_');
        }
        string name = sb.Length == 0 ? "Machina" : sb.ToString();
        if (char.IsAsciiDigit(name[0]) || Keywords.Contains(name) || IsGeneratedName(name))
        {
            name = "M_" + name;
        }
        return name.Length > MaxNameLength ? name[..MaxNameLength] : name;
    }

    /// <summary>True for names the KRL writer declares: <c>target«digits»</c> and the acceleration variable (KRL names ignore case).</summary>
    private static bool IsGeneratedName(string name) =>
        RapidNames.LooksLikeTarget(name) || string.Equals(name, KrlWriter.AccDefaultVariable, StringComparison.OrdinalIgnoreCase)
        || SystemRoutines.Contains(name);

    // Routines of the KUKA system software that every program calls in its INI fold; a module with one of these names would call itself.
    private static readonly HashSet<string> SystemRoutines = new(StringComparer.OrdinalIgnoreCase) { "BAS", "IR_STOPM" };

    /// <summary>Text for a comment: line breaks (also Unicode line separators) and other control characters become spaces, so the comment cannot end early.</summary>
    internal static string Comment(string text) => ProgramText.OneLine(text);
}

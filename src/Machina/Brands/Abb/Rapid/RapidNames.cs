using System.Text;

namespace Machina;

/// <summary>
/// Valid RAPID identifiers: an ASCII letter first, then letters, digits or '_', at most 32 characters, not a reserved word
/// and not a name the controller or this compiler already uses (predefined data, the data types and instructions it
/// writes). RAPID names ignore case.
/// </summary>
internal sealed class RapidNames
{
    private static readonly HashSet<string> Reserved = new(StringComparer.OrdinalIgnoreCase)
    {
        "ALIAS", "AND", "BACKWARD", "CASE", "CONNECT", "CONST", "DEFAULT", "DIV", "DO", "ELSE", "ELSEIF", "ENDFOR", "ENDFUNC",
        "ENDIF", "ENDMODULE", "ENDPROC", "ENDRECORD", "ENDTEST", "ENDTRAP", "ENDWHILE", "ERROR", "EXIT", "FALSE", "FOR", "FROM",
        "FUNC", "GOTO", "IF", "INOUT", "LOCAL", "MOD", "MODULE", "NOSTEPIN", "NOT", "NOVIEW", "OR", "PERS", "PROC", "RAISE",
        "READONLY", "RECORD", "RETRY", "RETURN", "STEP", "SYSMODULE", "TEST", "THEN", "TO", "TRUE", "TRYNEXT", "UNDO", "VAR",
        "VIEWONLY", "WHILE", "WITH", "XOR",
        // Names this compiler or the controller already gives a meaning.
        "main", "tool0", "wobj0", "load0", "fine", "vmax",
        "v5", "v10", "v20", "v30", "v40", "v50", "v60", "v80", "v100", "v150", "v200", "v300", "v400", "v500", "v600", "v800",
        "v1000", "v1500", "v2000", "v2500", "v3000", "v4000", "v5000", "v6000", "v7000",
        "z0", "z1", "z5", "z10", "z15", "z20", "z30", "z40", "z50", "z60", "z80", "z100", "z150", "z200",
        // Data types and instructions this compiler writes: a module-level name like these would hide them.
        "num", "bool", "string", "pos", "orient", "pose", "confdata", "extjoint", "robtarget", "jointtarget", "robjoint",
        "speeddata", "zonedata", "tooldata", "loaddata", "wobjdata", "signaldo", "signalao",
        "MoveL", "MoveJ", "MoveC", "MoveAbsJ", "WaitTime", "TPWrite", "SetDO", "SetAO", "ConfJ", "ConfL", "WorldAccLim",
    };

    /// <summary>True for names of the form <c>target«digits»</c>, which declared targets use.</summary>
    internal static bool LooksLikeTarget(string name) =>
        name.StartsWith("target", StringComparison.OrdinalIgnoreCase) && name.Length > 6 && name.AsSpan(6).IndexOfAnyExceptInRange('0', '9') < 0;

    private readonly HashSet<string> _used = new(Reserved, StringComparer.OrdinalIgnoreCase);

    /// <summary>
    /// Why <paramref name="pin"/> cannot name an ABB IO signal, or null. Signals are named in the controller's IO configuration and
    /// used as RAPID identifiers, so a number such as <c>1</c> names none; the same rule offline (SetDO) and online (AliasIO).
    /// </summary>
    internal static string? WhyNotSignal(string pin) => IsValid(pin)
        ? null
        : $"\"{(pin.Length <= 40 ? pin : pin[..37] + "...")}\" is not a RAPID signal name; ABB signals are named in the controller's IO configuration (e.g. DO_1).";

    /// <summary>True when <paramref name="name"/> is a syntactically valid RAPID identifier that is not a reserved word.</summary>
    internal static bool IsValid(string name)
    {
        if (name.Length == 0 || name.Length > RapidText.MaxIdentifierLength || !char.IsAsciiLetter(name[0]))
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
        return !Reserved.Contains(name);
    }

    /// <summary>
    /// A free, valid identifier as close as possible to <paramref name="wanted"/>: invalid characters become '_', a letter
    /// prefix is added when needed, the length is cut to 32 and a number is appended when the name is taken. The result is reserved.
    /// </summary>
    internal string Claim(string wanted, string prefix)
    {
        var sb = new StringBuilder(wanted.Length + prefix.Length);
        foreach (char c in wanted)
        {
            sb.Append(char.IsAsciiLetterOrDigit(c) || c == '_' ? c : '_');
        }
        if (sb.Length == 0 || !char.IsAsciiLetter(sb[0]))
        {
            sb.Insert(0, prefix);
        }
        string baseName = sb.Length > RapidText.MaxIdentifierLength ? sb.ToString(0, RapidText.MaxIdentifierLength) : sb.ToString();
        string name = baseName;
        for (int n = 2; _used.Contains(name); n++)
        {
            string suffix = "_" + Num.I(n);
            name = (baseName.Length + suffix.Length > RapidText.MaxIdentifierLength
                ? baseName[..(RapidText.MaxIdentifierLength - suffix.Length)]
                : baseName) + suffix;
        }
        _used.Add(name);
        return name;
    }
}

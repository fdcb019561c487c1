using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// One request from the host to the RAPID driver: <c>@id code ["text"] p1 p2 …;</c> (spec online §6.2).
/// Values are stored already rounded the way the original host rounded them; encoding prints them in shortest
/// invariant form (G15), with <see cref="UnusedAxis"/> printed as <c>9E9</c>.
/// </summary>
internal readonly partial struct AbbRequest
{
    /// <summary>Most numeric parameters one request can carry (the driver record has p1..p11).</summary>
    public const int MaxParameters = 11;

    /// <summary>Largest id the driver reads exactly: RAPID parses ids into a 32-bit float (bug A10 of the original).</summary>
    public const int MaxId = 8_388_608;

    /// <summary>Longest text parameter: a RAPID string holds at most 80 characters.</summary>
    public const int MaxTextLength = RapidFacts.MaxStringLength;

    /// <summary>The value RAPID uses for an external axis that is not in use; printed as <c>9E9</c>.</summary>
    public const double UnusedAxis = RapidFacts.UnusedAxis;

    private readonly Parameters _values;

    /// <summary>Creates a request from already rounded values; validates id, text and values.</summary>
    public AbbRequest(int id, int code, string? text, ReadOnlySpan<double> values)
    {
        if (id < 0 || id > MaxId)
        {
            throw new ArgumentOutOfRangeException(nameof(id), id, $"An ABB request id must be between 0 and {MaxId}: the driver reads ids as 32-bit floats.");
        }
        if (values.Length > MaxParameters)
        {
            throw new ArgumentException($"An ABB request carries at most {MaxParameters} numbers, but {values.Length} were given.", nameof(values));
        }
        if (text is not null)
        {
            ValidateText(text, nameof(text));
        }
        Id = id;
        Code = code;
        Text = text;
        ParameterCount = values.Length;
        for (int i = 0; i < values.Length; i++)
        {
            _values[i] = Num.Clean(Num.Finite(values[i], nameof(values)));
        }
    }

    private AbbRequest(int id, string statement)
    {
        Id = id;
        Code = 0;
        RawStatement = statement;
    }

    /// <summary>The action id echoed in the acknowledgement (0 = not acknowledged as an action).</summary>
    public int Id { get; }

    /// <summary>The instruction code (see <see cref="AbbInstructionCode"/>); 0 for a raw custom statement.</summary>
    public int Code { get; }

    /// <summary>The quoted text parameter (message, signal name), or null.</summary>
    public string? Text { get; }

    /// <summary>A custom statement sent verbatim after the id (CustomCode), or null for a regular request.</summary>
    public string? RawStatement { get; }

    /// <summary>How many numeric parameters the request carries.</summary>
    public int ParameterCount { get; }

    /// <summary>The numeric parameter at <paramref name="index"/> (0-based); missing parameters read as 0, like the driver.</summary>
    public double this[int index] => index >= 0 && index < ParameterCount ? _values[index] : 0;

    /// <summary>The instruction code as the enum (may be an undefined value for unknown codes).</summary>
    public AbbInstructionCode Instruction => (AbbInstructionCode)Code;

    /// <summary>A request whose statement is sent verbatim: <c>@id statement;</c> (CustomCode).</summary>
    public static AbbRequest Custom(int id, string statement)
    {
        ArgumentNullException.ThrowIfNull(statement);
        if (id < 0 || id > MaxId)
        {
            throw new ArgumentOutOfRangeException(nameof(id), id, $"An ABB request id must be between 0 and {MaxId}.");
        }
        if (WhyStatementCannotBeSent(statement) is string why)
        {
            throw new ArgumentException(why, nameof(statement));
        }
        return new AbbRequest(id, TrimStatement(statement));
    }

    /// <summary>Longest custom statement sent: the driver reads a code and 11 numbers of at most 80 characters each per request.</summary>
    public const int MaxStatementLength = 1000;

    /// <summary>Why <paramref name="statement"/> cannot be sent as a custom statement (a sentence), or null when it can.</summary>
    public static string? WhyStatementCannotBeSent(string statement)
    {
        ArgumentNullException.ThrowIfNull(statement);
        string trimmed = TrimStatement(statement);
        if (trimmed.Length == 0)
        {
            return "A custom ABB statement cannot be empty.";
        }
        if (trimmed.Length > MaxStatementLength)
        {
            return $"A custom ABB statement can be at most {MaxStatementLength} characters (what the driver reads of one request), but \"{Abbreviate(statement)}\" has {trimmed.Length}.";
        }
        foreach (char c in trimmed)
        {
            if (c == ';' || c > 126 || char.IsControl(c))
            {
                return $"A custom ABB statement must be one line of plain ASCII without ';', but got \"{Abbreviate(statement)}\".";
            }
        }
        return AbbStatementGrammar.WhyDriverCannotRead(trimmed) is string why
            ? $"A custom ABB statement is sent as a request to the Machina driver, which reads a numeric instruction code, at most one quoted text of up to {MaxTextLength} characters, then up to {MaxParameters} numbers: in \"{Abbreviate(statement)}\", {why}"
            : null;
    }

    private static string TrimStatement(string statement)
    {
        string trimmed = statement.Trim();
        return trimmed.EndsWith(';') ? trimmed[..^1].TrimEnd() : trimmed;
    }

    /// <summary>Throws when a text parameter would break the framing or not fit a RAPID string.</summary>
    public static void ValidateText(string text, string paramName)
    {
        if (WhyTextCannotBeSent(text) is string why)
        {
            throw new ArgumentException(why, paramName);
        }
    }

    /// <summary>
    /// Why <paramref name="text"/> cannot be sent as a text parameter (a sentence), or null when it can: it must fit a RAPID
    /// string and be plain ASCII without '"' or ';', which would break the framing.
    /// </summary>
    public static string? WhyTextCannotBeSent(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (text.Length > MaxTextLength)
        {
            return $"Text sent to an ABB robot can be at most {MaxTextLength} characters, but \"{Abbreviate(text)}\" has {text.Length}.";
        }
        foreach (char c in text)
        {
            if (c == '"' || c == ';' || c > 126 || char.IsControl(c))
            {
                return $"Text sent to an ABB robot must be plain ASCII without '\"' or ';', but got \"{text}\".";
            }
        }
        return null;
    }

    private static string Abbreviate(string text) => text.Length <= 40 ? text : text[..37] + "...";

    /// <summary>
    /// Makes any text safe to show on the pendant: '"' becomes '\'', ';' becomes ',', other non-ASCII or control
    /// characters become '?', and the result is cut to <see cref="MaxTextLength"/> characters.
    /// </summary>
    public static string SanitizeText(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        var chars = new char[Math.Min(text.Length, MaxTextLength)];
        for (int i = 0; i < chars.Length; i++)
        {
            char c = text[i];
            chars[i] = c switch
            {
                '"' => '\'',
                ';' => ',',
                _ when c > 126 || char.IsControl(c) => '?',
                _ => c,
            };
        }
        return new string(chars);
    }

    /// <summary>Eleven doubles stored inline, so a request never allocates.</summary>
    [InlineArray(MaxParameters)]
    private struct Parameters
    {
        private double _element;
    }
}

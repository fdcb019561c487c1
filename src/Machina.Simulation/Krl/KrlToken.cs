namespace Machina.Simulation.Krl;

/// <summary>What a KRL token is.</summary>
internal enum KrlTokenKind
{
    /// <summary>A name: a keyword, a variable, a routine or a system variable (<c>$VEL</c>).</summary>
    Name,

    /// <summary>A whole number.</summary>
    Int,

    /// <summary>A number with a decimal point or exponent.</summary>
    Real,

    /// <summary>A string in double quotes.</summary>
    String,

    /// <summary>An enumeration value (<c>#NAME</c>).</summary>
    Enum,

    /// <summary>An operator or punctuation.</summary>
    Symbol,

    /// <summary>The end of a line (KRL statements end there).</summary>
    EndOfLine,

    /// <summary>The end of the file.</summary>
    End,
}

/// <summary>A token of a KRL file, with its 1-based line.</summary>
/// <param name="Kind">What it is.</param>
/// <param name="Text">Its text (a string without its quotes).</param>
/// <param name="Line">The line it is on.</param>
internal sealed record KrlToken(KrlTokenKind Kind, string Text, int Line)
{
    /// <summary>True when this is the name or keyword <paramref name="word"/> (KRL ignores case).</summary>
    public bool Is(string word) => Kind == KrlTokenKind.Name && string.Equals(Text, word, StringComparison.OrdinalIgnoreCase);

    /// <summary>True when this is the symbol <paramref name="symbol"/>.</summary>
    public bool IsSymbol(string symbol) => Kind == KrlTokenKind.Symbol && Text == symbol;

    /// <summary>The token as an error message quotes it.</summary>
    public string Display => Kind switch
    {
        KrlTokenKind.EndOfLine => "the end of the line",
        KrlTokenKind.End => "the end of the file",
        KrlTokenKind.String => $"\"{Text}\"",
        KrlTokenKind.Enum => "#" + Text,
        _ => $"'{Text}'",
    };
}

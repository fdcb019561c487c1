namespace Machina.Simulation.Rapid;

/// <summary>What a RAPID token is.</summary>
internal enum RapidTokenKind
{
    /// <summary>A name or keyword (RAPID is not case sensitive).</summary>
    Name,

    /// <summary>A numeric literal.</summary>
    Number,

    /// <summary>A string literal (its value, escapes resolved).</summary>
    String,

    /// <summary>An operator or punctuation, e.g. <c>:=</c> or <c>\</c>.</summary>
    Symbol,

    /// <summary>The end of the module text.</summary>
    End,
}

/// <summary>One token of a RAPID module, with its 1-based line.</summary>
internal readonly record struct RapidToken(RapidTokenKind Kind, string Text, double Number, int Line)
{
    /// <summary>True when this is the name or keyword <paramref name="word"/> (any case).</summary>
    public bool Is(string word) => Kind == RapidTokenKind.Name && string.Equals(Text, word, StringComparison.OrdinalIgnoreCase);

    /// <summary>True when this is the symbol <paramref name="symbol"/>.</summary>
    public bool IsSymbol(string symbol) => Kind == RapidTokenKind.Symbol && Text == symbol;
}

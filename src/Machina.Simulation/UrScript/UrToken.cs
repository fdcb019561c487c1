namespace Machina.Simulation.UrScript;

/// <summary>The kinds of URScript tokens.</summary>
internal enum UrTokenKind
{
    /// <summary>A name: variable, function or keyword.</summary>
    Name,

    /// <summary>An integer literal.</summary>
    Int,

    /// <summary>A floating-point literal.</summary>
    Float,

    /// <summary>A string literal (quotes removed).</summary>
    String,

    /// <summary>An operator or punctuation mark.</summary>
    Symbol,

    /// <summary>The end of a line.</summary>
    Newline,

    /// <summary>The end of the text.</summary>
    End,
}

/// <summary>One token of URScript text with its 1-based line and column.</summary>
internal readonly record struct UrToken(UrTokenKind Kind, string Text, int Line, int Column, double Number = 0)
{
    /// <summary>True for the symbol or name <paramref name="text"/>.</summary>
    public bool Is(string text) => (Kind == UrTokenKind.Symbol || Kind == UrTokenKind.Name) && Text == text;
}

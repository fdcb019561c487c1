namespace Machina.Simulation.Krl;

/// <summary>
/// <c>GOTO name</c>: the program goes on at the line <c>name:</c> of the same routine. As KRL allows, the label is in the block of
/// the GOTO or in one around it (a jump out of a loop, IF or SWITCH); a jump into a block from outside stops the program.
/// </summary>
internal sealed class KrlGoto(int line, string label) : KrlStmt(line)
{
    /// <summary>The label's name.</summary>
    public string Label { get; } = label;
}

/// <summary>A jump label <c>name:</c> on a line of its own (does nothing when reached).</summary>
internal sealed class KrlLabel(int line, string name) : KrlStmt(line)
{
    /// <summary>The label's name.</summary>
    public string Name { get; } = name;

    /// <summary>The index of the label named <paramref name="name"/> in <paramref name="body"/> (not in nested blocks), or -1.</summary>
    public static int IndexIn(List<KrlStmt> body, string name) =>
        body.FindIndex(s => s is KrlLabel label && string.Equals(label.Name, name, StringComparison.OrdinalIgnoreCase));

    /// <summary>True when <paramref name="body"/> or a block nested in it has the label <paramref name="name"/>.</summary>
    public static bool Within(List<KrlStmt> body, string name) => body.Exists(s => s switch
    {
        KrlLabel label => string.Equals(label.Name, name, StringComparison.OrdinalIgnoreCase),
        KrlIf branch => Within(branch.Then, name) || Within(branch.Else, name),
        KrlLoop loop => Within(loop.Body, name),
        KrlFor loop => Within(loop.Body, name),
        KrlSwitch choice => choice.Cases.Exists(c => Within(c.Body, name)) || (choice.Default is { } d && Within(d, name)),
        _ => false,
    });
}

/// <summary>Reading GOTO and labels.</summary>
internal sealed partial class KrlParser
{
    /// <summary>True when the line is <c>name:</c> alone (a jump label).</summary>
    private bool IsLabel() => Peek.Kind == KrlTokenKind.Name && PeekAt(1).IsSymbol(":")
        && PeekAt(2).Kind is KrlTokenKind.EndOfLine or KrlTokenKind.End && !KrlKeywords.IsReserved(Peek.Text);

    private KrlLabel Label()
    {
        KrlToken name = Peek;
        _at += 2;
        EndOfLine();
        return new KrlLabel(name.Line, name.Text);
    }

    private KrlGoto Goto()
    {
        KrlToken keyword = Peek;
        _at++;
        KrlToken label = Peek;
        if (label.Kind != KrlTokenKind.Name)
        {
            throw Error(label, $"GOTO needs the name of a label, not {label.Display}");
        }
        _at++;
        EndOfLine();
        return new KrlGoto(keyword.Line, label.Text);
    }
}

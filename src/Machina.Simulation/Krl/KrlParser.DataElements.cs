namespace Machina.Simulation.Krl;

/// <summary>
/// An array element given its value in a data list (<c>EVENT_TYPES[7] = #SWITCH_OK</c> after <c>DECL … EVENT_TYPES[13]</c>), as
/// KRL allows there: constant indices and a constant value.
/// </summary>
internal sealed partial class KrlParser
{
    /// <summary>True when the line is NAME[…] = … (not a declaration).</summary>
    private bool IsElementInitialiser() => Peek.Kind == KrlTokenKind.Name && PeekAt(1).IsSymbol("[")
        && KrlUserTypes.Find(_userTypes, Peek.Text) is null && !KrlKeywords.IsReserved(Peek.Text);

    private KrlElementInitialiser ElementInitialiser()
    {
        KrlToken name = Peek;
        _at += 2;
        var indices = new List<int>();
        if (Accept("]"))
        {
            // NAME[] = "text": a whole CHAR array given its text.
            Expect("=");
            KrlExpr text = Expression();
            EndOfLine();
            return new KrlElementInitialiser(name.Text, [], text, name.Line);
        }
        do
        {
            KrlToken index = Peek;
            if (index.Kind != KrlTokenKind.Int)
            {
                throw Error(index, $"an element of a data list's array is given with constant indices, not {index.Display}");
            }
            indices.Add(Whole(index));
            _at++;
        }
        while (Accept(","));
        Expect("]");
        Expect("=");
        KrlExpr value = Expression();
        EndOfLine();
        return new KrlElementInitialiser(name.Text, [.. indices], value, name.Line);
    }
}

/// <summary>NAME[indices] = value in a data list (no indices: NAME[] = "text", a whole CHAR array).</summary>
internal sealed record KrlElementInitialiser(string Name, int[] Indices, KrlExpr Value, int Line);

namespace Machina.Simulation.Krl;

/// <summary>
/// EXT and EXTFCT declarations (<c>EXT BAS (BAS_COMMAND :IN, REAL :IN)</c>, <c>EXTFCT INT name(…)</c>): they tell the compiler
/// a routine of another module or of the system; the twin notes the name and its load checks that such a routine exists.
/// </summary>
internal sealed partial class KrlParser
{
    /// <summary>Where the EXT and EXTFCT declarations of the file being read go.</summary>
    private List<KrlExternal> _externals = [];

    /// <summary>True when the line starts EXT or EXTFCT (not a call or an assignment of a variable called so).</summary>
    private bool IsExternal() => (Peek.Is("EXT") || Peek.Is("EXTFCT")) && PeekAt(1).Kind == KrlTokenKind.Name;

    /// <summary>EXT name(parameters) or EXTFCT type name(parameters): the parameter list is read to its closing bracket.</summary>
    private void External()
    {
        bool function = Peek.Is("EXTFCT");
        _at++;
        if (function)
        {
            // The return type may be one of the program's own (a STRUC or ENUM the twin does not declare): any name.
            Identifier("the function's return type");
        }
        KrlToken name = Peek;
        string routine = Identifier("the routine's name");
        Expect("(");
        int depth = 1;
        while (depth > 0)
        {
            KrlToken token = Peek;
            if (token.Kind is KrlTokenKind.EndOfLine or KrlTokenKind.End)
            {
                throw Error(token, $"')' is missing in the declaration of {routine}");
            }
            depth += token.IsSymbol("(") ? 1 : token.IsSymbol(")") ? -1 : 0;
            _at++;
        }
        EndOfLine();
        _externals.Add(new KrlExternal(routine, _file, name.Line));
    }
}

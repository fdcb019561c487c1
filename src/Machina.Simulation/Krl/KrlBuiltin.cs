namespace Machina.Simulation.Krl;

/// <summary>What a built-in routine accepts as one argument.</summary>
/// <param name="Accepts">The type accepted (null: any value); INT and REAL accept each other.</param>
/// <param name="IsOut">True for an OUT argument: a variable the routine writes.</param>
/// <param name="Optional">True when a call may leave it out (only the last parameters are optional).</param>
internal sealed record KrlBuiltinParameter(KrlType? Accepts, bool IsOut = false, bool Optional = false)
{
    /// <summary>Any CHAR array (a string).</summary>
    public static KrlBuiltinParameter Text { get; } = new(KrlType.Array(KrlType.Char, 0));

    /// <summary>A REAL (or INT) value.</summary>
    public static KrlBuiltinParameter Real { get; } = new(KrlType.Real);

    /// <summary>An INT (or REAL) value.</summary>
    public static KrlBuiltinParameter Int { get; } = new(KrlType.Int);
}

/// <summary>
/// A routine of the KUKA system software or of a technology package (EthernetKRL) that programs call: its parameters, its
/// return type (null for a subprogram) and what it does on the twin. OUT arguments arrive as <see cref="KrlPlace"/>.
/// </summary>
internal sealed record KrlBuiltin(string Name, KrlType? Returns, KrlBuiltinParameter[] Parameters, Func<KrlMachine, object[], object?> Run)
{
    /// <summary>
    /// True when the routine writes no program variable except through its OUT arguments, and whatever else of the controller it
    /// changes that a WAIT FOR or an interrupt's condition can read (a flag, a channel) tells the inputs' version: a call then makes
    /// the interpreter look at the interrupts' conditions again only when an OUT argument is a variable a condition reads.
    /// </summary>
    public bool WritesOnlyArguments { get; init; }

    /// <summary>True when the value returned is made by each call and kept by nobody: an assignment may take it without a copy.</summary>
    public bool ReturnsFresh { get; init; }
}

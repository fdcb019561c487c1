namespace Machina.Simulation.Rapid;

/// <summary>A parameter of a built-in instruction or function.</summary>
/// <param name="Name">The name (optional arguments are given by it: <c>\WObj:=wobj0</c>).</param>
/// <param name="Type">The type name, or null for any type.</param>
/// <param name="Optional">True for an optional argument.</param>
/// <param name="Switch">True for a switch (an optional argument without value, e.g. <c>\Off</c>).</param>
/// <param name="Ref">True when the argument must be data the routine may write (VAR, PERS or INOUT).</param>
/// <param name="Rank">The array's dimensions for an array parameter (<c>{*}</c>), 0 otherwise.</param>
internal sealed record RapidBuiltinParam(string Name, string? Type, bool Optional = false, bool Switch = false, bool Ref = false, int Rank = 0);

/// <summary>A predefined instruction (procedure) or function of the twin, with its parameters and what it does.</summary>
internal sealed class RapidBuiltin(string name, string? returns, RapidBuiltinParam[] parameters, Func<RapidCall, object?> run)
{
    /// <summary>The name (case is ignored when a program calls it).</summary>
    public string Name { get; } = name;

    /// <summary>The type a function returns, or null for an instruction.</summary>
    public string? Returns { get; } = returns;

    /// <summary>The parameters, required ones in order, optional ones anywhere.</summary>
    public RapidBuiltinParam[] Parameters { get; } = parameters;

    /// <summary>Runs it; returns the function's value (null for an instruction).</summary>
    public Func<RapidCall, object?> Run { get; } = run;

    /// <summary>A required parameter.</summary>
    public static RapidBuiltinParam P(string name, string? type, bool reference = false) => new(name, type, Ref: reference);

    /// <summary>An optional parameter.</summary>
    public static RapidBuiltinParam Opt(string name, string? type, bool reference = false) => new(name, type, Optional: true, Ref: reference);

    /// <summary>A switch.</summary>
    public static RapidBuiltinParam Sw(string name) => new(name, "switch", Optional: true, Switch: true);
}

/// <summary>What a call refers to, found by the binder: a built-in or a routine of the program, and which argument feeds which parameter.</summary>
internal sealed class RapidCallTarget(RapidBuiltin? builtin, RapidRoutine? routine, int[] argumentOf)
{
    /// <summary>The built-in, or null.</summary>
    public RapidBuiltin? Builtin { get; } = builtin;

    /// <summary>The program's routine, or null.</summary>
    public RapidRoutine? Routine { get; } = routine;

    /// <summary>For each parameter, the index of its argument, or -1 when it is absent.</summary>
    public int[] ArgumentOf { get; } = argumentOf;

    /// <summary>True when no argument calls a function (so evaluating the arguments writes no data), set by the binder.</summary>
    public bool ArgumentsCallNoFunction { get; init; }
}

/// <summary>A call of a built-in as it runs: its arguments (evaluated when asked) and the task it runs in.</summary>
internal readonly struct RapidCall(RapidMachine machine, RapidFrame? frame, RapidArg[] args, RapidCallTarget target, int line)
{
    /// <summary>The task's machine.</summary>
    public RapidMachine Machine => machine;

    /// <summary>The line of the call.</summary>
    public int Line { get; } = line;

    /// <summary>True when parameter <paramref name="p"/> was given.</summary>
    public bool Has(int p) => target.ArgumentOf[p] >= 0;

    /// <summary>The value of parameter <paramref name="p"/> (the live data for a reference).</summary>
    public object Value(int p) => machine.Evaluate(args[target.ArgumentOf[p]].Value!, frame);

    /// <summary>A num parameter.</summary>
    public double Num(int p) => machine.Number(args[target.ArgumentOf[p]].Value!, frame); // arithmetic computed without a box

    /// <summary>A string parameter.</summary>
    public string Str(int p) => (string)Value(p);

    /// <summary>
    /// A string parameter read in place: when its argument is a call of StrPart (<c>StrToVal(StrPart(chunk, i, n), v)</c>), the part of
    /// StrPart's string, with StrPart's arguments evaluated and checked as StrPart does, without a new string for it.
    /// </summary>
    public ReadOnlySpan<char> Text(int p)
    {
        if (args[target.ArgumentOf[p]].Value is RapidCallExpr { Target: { } part } call && ReferenceEquals(part.Builtin, RapidBuiltins.StrPart))
        {
            (string s, int start, int length) = RapidBuiltins.Part(new RapidCall(machine, frame, call.Args, part, call.Line));
            return s.AsSpan(start, length);
        }
        return Str(p);
    }

    /// <summary>A record parameter.</summary>
    public RapidRecord Record(int p) => (RapidRecord)Value(p);

    /// <summary>
    /// A record parameter and where it was read (<paramref name="read"/>: the cell of its data, taken with its write count before the
    /// read), so that a later read can tell it is the same value unchanged (<see cref="RapidCellMark.Same"/>).
    /// </summary>
    public RapidRecord Record(int p, out RapidCellMark read)
    {
        RapidCell? cell = DataCell(p);
        long version = cell?.Version ?? 0;
        RapidRecord value = Record(p);
        read = new RapidCellMark(cell, value, version);
        return value;
    }

    /// <summary>The static type of parameter <paramref name="p"/>'s argument.</summary>
    public RapidDataType? TypeOf(int p) => args[target.ArgumentOf[p]].Value!.Type;

    /// <summary>The name of the data given for parameter <paramref name="p"/> (<c>sync1</c>), or null when it is not a plain name.</summary>
    public string? DataName(int p) => (args[target.ArgumentOf[p]].Value as RapidName)?.Name;

    /// <summary>
    /// The cell of the data given for parameter <paramref name="p"/> or of the data its component or element belongs to
    /// (<c>rec.x</c>, <c>arr{2}</c>: the cell of <c>rec</c>, <c>arr</c>), or null when the argument is no data.
    /// </summary>
    public RapidCell? DataCell(int p)
    {
        return args[target.ArgumentOf[p]].Value!.Root is RapidName name ? name.Global ?? frame?.Cells[name.Slot] : null;
    }

    /// <summary>Writes <paramref name="value"/> into the data given for parameter <paramref name="p"/>.</summary>
    public void Set(int p, object value) => machine.Store(args[target.ArgumentOf[p]].Value!, frame, value);

    /// <summary>A run-time error at this call.</summary>
    public RapidRuntimeException Error(int errno, string message) => new(errno, Line, message);
}

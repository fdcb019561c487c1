namespace Machina.Simulation.Krl;

/// <summary>A variable of a data list or a system variable: its type and value.</summary>
internal sealed class KrlCell(string name, KrlType type, object value)
{
    /// <summary>The storage: one slot holding the value (places point into it).</summary>
    public object[] Box { get; } = [value];

    /// <summary>The name.</summary>
    public string Name { get; } = name;

    /// <summary>The type.</summary>
    public KrlType Type { get; } = type;

    /// <summary>The value (the controller's interpreter owns it).</summary>
    public object Value
    {
        get => Read is null ? Box[0] : Read();
        set => Box[0] = value;
    }

    /// <summary>True for a system variable a program may not write (e.g. <c>$POS_ACT</c>).</summary>
    public bool ReadOnly { get; init; }

    /// <summary>For a system variable the controller computes when read (e.g. <c>$AXIS_ACT</c>), how.</summary>
    public Func<object>? Read { get; init; }

    /// <summary>
    /// True once an interrupt's condition reads the variable (set when the interrupt is declared, never cleared): only then may an
    /// interpreter's write of one of its elements make a condition change.
    /// </summary>
    public bool Watched => _watchedWrites is not null;

    /// <summary>The controller's count of writes of watched variables, once the variable is watched.</summary>
    private KrlWatchedWrites? _watchedWrites;

    /// <summary>Marks the variable as read by an interrupt's condition: its writes count in <paramref name="writes"/> from now on.</summary>
    public void Watch(KrlWatchedWrites writes) => _watchedWrites ??= writes;

    /// <summary>The controller's wake-up of a waiting WAIT FOR, once a WAIT FOR's or an interrupt's condition reads the variable.</summary>
    private KrlWaitWake? _wakes;

    /// <summary>True once a WAIT FOR's or an interrupt's condition reads the variable: its writes wake a waiting WAIT FOR.</summary>
    public bool WakesOnWrite => _wakes is not null;

    /// <summary>Marks the variable as read by a WAIT FOR's or an interrupt's condition (when the program is loaded): its writes wake a waiting WAIT FOR.</summary>
    public void WakeOnWrite(KrlWaitWake wakes) => _wakes ??= wakes;

    /// <summary>
    /// Counts a program's write of the variable or an element of it, when an interrupt's condition reads it, and wakes a WAIT FOR
    /// waiting in either interpreter when a condition reads it.
    /// </summary>
    public void CountWrite()
    {
        _watchedWrites?.Add();
        _wakes?.Wrote();
    }

    /// <summary>Called after a program wrote the variable or an element of it (the element's index, or -1 for all of it).</summary>
    public Action<int>? Written { get; init; }

    /// <summary>For an IO array (<c>$IN</c>, <c>$OUT</c>, <c>$ANIN</c>, <c>$ANOUT</c>), where its values are (<see cref="Box"/> is unused then).</summary>
    public KrlSignalArray? Signals { get; private init; }

    /// <summary>The system variable of an IO array, whose values are the controller's <see cref="Twin.TwinIo"/> bank.</summary>
    public static KrlCell Of(KrlSignalArray signals, bool readOnly, Action<int>? written = null) =>
        new(signals.Name, signals.Type, null!) { Signals = signals, Read = signals.Get, ReadOnly = readOnly, Written = written };
}

/// <summary>A parameter of a routine: name, IN (by value) or OUT (by reference), and its type from the routine's DECL.</summary>
internal sealed class KrlParameter(string name, bool isOut, bool isArray)
{
    /// <summary>The name.</summary>
    public string Name { get; } = name;

    /// <summary>True for <c>:OUT</c>: the caller's variable is changed.</summary>
    public bool IsOut { get; } = isOut;

    /// <summary>True when written <c>name[]</c>.</summary>
    public bool IsArray { get; } = isArray;

    /// <summary>The type (set when the routine's declarations are read).</summary>
    public KrlType Type { get; set; } = KrlType.Int;
}

/// <summary>A DEF subprogram or a DEFFCT function of a file.</summary>
internal sealed class KrlRoutine(string file, string name, int line)
{
    /// <summary>The file it is in.</summary>
    public string File { get; } = file;

    /// <summary>Its name.</summary>
    public string Name { get; } = name;

    /// <summary>The line of its DEF or DEFFCT.</summary>
    public int Line { get; } = line;

    /// <summary>The module (file name without extension) it belongs to.</summary>
    public string Module { get; init; } = "";

    /// <summary>For a function, its return type (null for a subprogram).</summary>
    public KrlType? ReturnType { get; init; }

    /// <summary>True when GLOBAL (callable from other modules); the first routine of a file is too.</summary>
    public bool IsGlobal { get; init; }

    /// <summary>The parameters, in order.</summary>
    public List<KrlParameter> Parameters { get; } = [];

    /// <summary>Every local variable (parameters first): name, type, line of its DECL.</summary>
    public List<(string Name, KrlType Type, int Line)> Locals { get; } = [];

    /// <summary>The statements.</summary>
    public List<KrlStmt> Body { get; } = [];

    /// <summary>
    /// The locals' types in slot order, and the array elements they hold together: taken once, at the routine's first call (its
    /// locals are declared at the load and never change after). A call read them from the list of named tuples, twice, at every
    /// call: the driver makes two routine calls an action.
    /// </summary>
    public FrameLayout Frame => _frame ??= FrameOf(Locals);

    private FrameLayout? _frame;

    /// <summary>What the routine does with its IN parameters (found at its first call, see <see cref="KrlRoutineReads"/>).</summary>
    public KrlRoutineReads Reads => _reads ??= KrlRoutineReads.Of(this);

    private KrlRoutineReads? _reads;

    /// <summary>A routine's locals as a call makes them (one object, so that two interpreters that take it at once see it whole).</summary>
    /// <param name="Types">The locals' types in slot order.</param>
    /// <param name="Elements">The array elements of its local arrays together.</param>
    internal sealed record FrameLayout(KrlType[] Types, long Elements);

    private static FrameLayout FrameOf(List<(string Name, KrlType Type, int Line)> locals)
    {
        var types = new KrlType[locals.Count];
        long elements = 0;
        for (int i = 0; i < types.Length; i++)
        {
            types[i] = locals[i].Type;
            if (types[i].Kind == KrlKind.Array)
            {
                elements += types[i].Length;
            }
        }
        return new FrameLayout(types, elements);
    }

    /// <summary>The slot of a local or parameter, or -1.</summary>
    public int SlotOf(string name) => Locals.FindIndex(l => string.Equals(l.Name, name, StringComparison.OrdinalIgnoreCase));
}

/// <summary>A module: a .src file's routines and its .dat data list of the same name.</summary>
internal sealed class KrlModule(string name)
{
    /// <summary>The module's name.</summary>
    public string Name { get; } = name;

    /// <summary>The routines, in file order.</summary>
    public List<KrlRoutine> Routines { get; } = [];

    /// <summary>The data list's variables.</summary>
    public Dictionary<string, KrlCell> Data { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The data list's variables declared GLOBAL in a PUBLIC data list (visible to every module).</summary>
    public HashSet<string> GlobalData { get; } = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>The routines its EXT and EXTFCT declarations name (each must be loaded or be a system routine).</summary>
    public List<KrlExternal> Externals { get; } = [];
}

/// <summary>An EXT or EXTFCT declaration: the routine it names, in a file at a line.</summary>
internal sealed record KrlExternal(string Name, string File, int Line);

/// <summary>
/// How many times a program wrote a variable that an interrupt's condition reads (any of them, any interpreter's thread): an
/// interpreter whose timer counts looks at its conditions again only after this changed.
/// </summary>
internal sealed class KrlWatchedWrites
{
    private long _count;

    /// <summary>The count now.</summary>
    public long Count => Volatile.Read(ref _count);

    /// <summary>Counts one write.</summary>
    public void Add() => Interlocked.Increment(ref _count);
}

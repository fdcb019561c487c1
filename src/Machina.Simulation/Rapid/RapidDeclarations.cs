namespace Machina.Simulation.Rapid;

/// <summary>How data is stored: a constant, a variable, or a persistent shared by the tasks and kept between runs.</summary>
internal enum RapidStorage
{
    /// <summary><c>CONST</c></summary>
    Const,

    /// <summary><c>VAR</c></summary>
    Var,

    /// <summary><c>PERS</c></summary>
    Pers,
}

/// <summary>A data declaration: <c>VAR num a{3} := [1, 2, 3];</c></summary>
internal sealed record RapidDataDecl(int Line, RapidStorage Storage, string TypeName, string Name, RapidExpr[] Dimensions, RapidExpr? Initial, bool Local);

/// <summary>A record type declared in a module: <c>RECORD name … ENDRECORD</c>.</summary>
internal sealed record RapidRecordDecl(int Line, string Name, List<(string TypeName, string Name)> Fields);

/// <summary>How a parameter is passed.</summary>
internal enum RapidParamMode
{
    /// <summary>By value (the routine gets a copy).</summary>
    In,

    /// <summary><c>VAR</c>: a variable of the caller, by reference.</summary>
    Var,

    /// <summary><c>PERS</c>: a persistent of the caller, by reference.</summary>
    Pers,

    /// <summary><c>INOUT</c>: any data of the caller, by reference.</summary>
    InOut,
}

/// <summary>A routine parameter: <c>\VAR num x{*}</c>, <c>\switch On</c>.</summary>
internal sealed record RapidParam(string Name, string TypeName, RapidParamMode Mode, bool Optional, int Rank)
{
    /// <summary>True for a <c>switch</c> (an optional argument without value); known once, asked at every call.</summary>
    public bool IsSwitch { get; } = string.Equals(TypeName, "switch", StringComparison.OrdinalIgnoreCase);
}

/// <summary>What kind of routine.</summary>
internal enum RapidRoutineKind
{
    /// <summary><c>PROC</c>: an instruction.</summary>
    Proc,

    /// <summary><c>FUNC</c>: returns a value.</summary>
    Func,

    /// <summary><c>TRAP</c>: runs on an interrupt.</summary>
    Trap,
}

/// <summary>A routine: PROC, FUNC or TRAP, with its local data, statements and error handler.</summary>
internal sealed class RapidRoutine(int line, RapidRoutineKind kind, string name, string? returnType, List<RapidParam> parameters, bool local)
{
    /// <summary>The line of its header.</summary>
    public int Line { get; } = line;

    /// <summary>PROC, FUNC or TRAP.</summary>
    public RapidRoutineKind Kind { get; } = kind;

    /// <summary>The name.</summary>
    public string Name { get; } = name;

    /// <summary>The type a FUNC returns.</summary>
    public string? ReturnTypeName { get; } = returnType;

    /// <summary>The parameters, in order.</summary>
    public List<RapidParam> Parameters { get; } = parameters;

    /// <summary>True when it is LOCAL to its module.</summary>
    public bool Local { get; } = local;

    /// <summary>Its local data declarations.</summary>
    public List<RapidDataDecl> Data { get; } = [];

    /// <summary>Its statements.</summary>
    public List<RapidStmt> Body { get; } = [];

    /// <summary>The ERROR handler's statements, or null.</summary>
    public List<RapidStmt>? ErrorHandler { get; set; }

    /// <summary>The error numbers the ERROR handler takes (<c>ERROR (ERR_A, ERR_B)</c>), or null when it takes every error.</summary>
    public List<RapidExpr>? ErrorList { get; set; }

    /// <summary>The UNDO handler's statements (run when an error or ExitCycle ends the routine early), or null.</summary>
    public List<RapidStmt>? UndoHandler { get; set; }

    /// <summary>The module it is in.</summary>
    public RapidModule? Module { get; set; }

    /// <summary>How many local slots a call needs (parameters, local data, FOR variables), set by the binder.</summary>
    public int FrameSize { get; set; }

    /// <summary>The static types of the parameters and of the local data (by slot), set by the binder.</summary>
    public List<RapidDataType> SlotTypes { get; } = [];

    /// <summary>The type a FUNC returns, set by the binder.</summary>
    public RapidDataType? ReturnType { get; set; }

    /// <summary>
    /// By parameter: true when the routine may write it (assigns it or a part of it, or passes it on by reference); every parameter is
    /// IN (none shares the caller's data) when <see cref="TakesValuesOnly"/>. Set by the binder.
    /// </summary>
    public bool[] WritesParameter { get; set; } = [];

    /// <summary>True when every parameter is IN (or a switch): the routine writes no data of its caller through a parameter.</summary>
    public bool TakesValuesOnly { get; set; }

    /// <summary>A frame of an earlier call that returned normally, kept for the next call (see <see cref="RapidFrame.Reuse"/>).</summary>
    private RapidFrame? _spare;

    /// <summary>Takes the spare frame, if there is one (a recursive call finds none while the outer call runs).</summary>
    public RapidFrame? TakeSpareFrame() => Interlocked.Exchange(ref _spare, null);

    /// <summary>Keeps <paramref name="frame"/>, whose call returned normally, for the next call.</summary>
    public void KeepSpareFrame(RapidFrame frame) => Volatile.Write(ref _spare, frame);
}

/// <summary>A module: <c>MODULE name (attributes) … ENDMODULE</c>.</summary>
internal sealed class RapidModule(int line, string name, IReadOnlyList<string> attributes)
{
    /// <summary>The line of <c>MODULE</c>.</summary>
    public int Line { get; } = line;

    /// <summary>The module's name.</summary>
    public string Name { get; } = name;

    /// <summary>Its attributes, e.g. SYSMODULE, NOSTEPIN, VIEWONLY, READONLY, NOVIEW.</summary>
    public IReadOnlyList<string> Attributes { get; } = attributes;

    /// <summary>Its record types.</summary>
    public List<RapidRecordDecl> Records { get; } = [];

    /// <summary>Its data.</summary>
    public List<RapidDataDecl> Data { get; } = [];

    /// <summary>Its routines.</summary>
    public List<RapidRoutine> Routines { get; } = [];
}

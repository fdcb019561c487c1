namespace Machina.Simulation.Krl;

/// <summary>An expression of a KRL program; the binder fills in its type.</summary>
internal abstract class KrlExpr(int line, KrlNode node)
{
    /// <summary>The line it is on.</summary>
    public int Line { get; } = line;

    /// <summary>What kind of expression it is (the interpreter switches on it: one jump instead of a test per kind).</summary>
    public KrlNode Node { get; } = node;

    /// <summary>Its type, set when the program is bound.</summary>
    public KrlType Type { get; set; } = KrlType.Int;
}

/// <summary>An argument left out of a call (<c>f(a, , c)</c>): the parameter gets no value from the caller.</summary>
internal sealed class KrlOmitted(int line) : KrlExpr(line, KrlNode.Omitted);

/// <summary>A constant: INT, REAL, BOOL, an enumeration value or a string (a CHAR array).</summary>
internal sealed class KrlLiteral(int line, object value) : KrlExpr(line, KrlNode.Literal)
{
    /// <summary>The value (a string for a string literal: the binder makes equal ones of a program one string, see <see cref="KrlBinder"/>).</summary>
    public object Value { get; internal set; } = value;
}

/// <summary>A variable, a parameter or a system variable.</summary>
internal sealed class KrlName(int line, string name) : KrlExpr(line, KrlNode.Name)
{
    /// <summary>The name as written.</summary>
    public string Name { get; } = name;

    /// <summary>The variable of a data list or a system variable (null for a local).</summary>
    public KrlCell? Cell { get; set; }

    /// <summary>The slot of a local variable or parameter in its routine's frame (-1 for a cell).</summary>
    public int Slot { get; set; } = -1;
}

/// <summary>An array element, a row of a CHAR array (<c>text[i, ]</c>) or a whole array (<c>text[]</c>).</summary>
internal sealed class KrlIndex(int line, KrlExpr target, IReadOnlyList<KrlExpr?> indices) : KrlExpr(line, KrlNode.Index)
{
    /// <summary>The array.</summary>
    public KrlExpr Target { get; } = target;

    /// <summary>The indices (null: an index left out; none: the whole array).</summary>
    public IReadOnlyList<KrlExpr?> Indices => Each;

    /// <summary>The same indices as an array (the interpreter reads them at every element access).</summary>
    public KrlExpr?[] Each { get; } = [.. indices];

    /// <summary>How the interpreter reads it (set by the binder, which knows the target's variable).</summary>
    public KrlAccess Access { get; set; }
}

/// <summary>A component of a structure (<c>$VEL.CP</c>).</summary>
internal sealed class KrlMember(int line, KrlExpr target, string field) : KrlExpr(line, KrlNode.Member)
{
    /// <summary>The structure.</summary>
    public KrlExpr Target { get; } = target;

    /// <summary>The component's name.</summary>
    public string Field { get; } = field;

    /// <summary>The component's index in the structure type (set by the binder).</summary>
    public int FieldIndex { get; set; }
}

/// <summary>A call of a routine or of a built-in function.</summary>
internal sealed class KrlCall(int line, string name, IReadOnlyList<KrlExpr> arguments) : KrlExpr(line, KrlNode.Call)
{
    /// <summary>The routine's name.</summary>
    public string Name { get; } = name;

    /// <summary>The arguments.</summary>
    public IReadOnlyList<KrlExpr> Arguments => Each;

    /// <summary>The same arguments as an array (the interpreter reads them at every call).</summary>
    public KrlExpr[] Each { get; } = [.. arguments];

    /// <summary>The program's routine (set by the binder), or null for a built-in.</summary>
    public KrlRoutine? Routine { get; set; }

    /// <summary>The built-in (set by the binder), or null for a routine of the program.</summary>
    public KrlBuiltin? Builtin { get; set; }

    /// <summary>
    /// Bit i set: argument i is a local of the calling routine that the called routine's IN parameter may hold as it is, without
    /// a copy (set when the calling routine is first called, see <see cref="KrlRoutineReads"/>).
    /// </summary>
    public int SharedArguments { get; set; }
}

/// <summary>NOT, B_NOT or a minus sign.</summary>
internal sealed class KrlUnary(int line, string op, KrlExpr operand) : KrlExpr(line, KrlNode.Unary)
{
    /// <summary>The operator (upper case).</summary>
    public string Op { get; } = op;

    /// <summary>The operand.</summary>
    public KrlExpr Operand { get; } = operand;
}

/// <summary>An arithmetic, logic or comparison operation.</summary>
internal sealed class KrlBinary(int line, string op, KrlExpr left, KrlExpr right) : KrlExpr(line, KrlNode.Binary)
{
    private static readonly string[] Ops = ["+", "-", "*", "/", "AND", "OR", "EXOR", "B_AND", "B_OR", "B_EXOR", "==", "<>", "<", "<=", ">", ">="];

    /// <summary>The operator (upper case for words).</summary>
    public string Op { get; } = op;

    /// <summary>The operator's index in + - * / AND OR EXOR B_AND B_OR B_EXOR == &lt;&gt; &lt; &lt;= &gt; &gt;= (fast to switch on).</summary>
    public int Code { get; } = Array.IndexOf(Ops, op);

    /// <summary>The left operand.</summary>
    public KrlExpr Left { get; } = left;

    /// <summary>The right operand.</summary>
    public KrlExpr Right { get; } = right;
}

/// <summary>An aggregate: <c>{E6POS: X 1, Y 2}</c> or <c>{X 1, Y 2}</c>, the components left out keep their values.</summary>
internal sealed class KrlAggregate(int line, string? typeName, IReadOnlyList<(string Field, KrlExpr Value)> fields) : KrlExpr(line, KrlNode.Aggregate)
{
    /// <summary>The type written before the colon, or null.</summary>
    public string? TypeName { get; } = typeName;

    /// <summary>The components given, in order.</summary>
    public IReadOnlyList<(string Field, KrlExpr Value)> Fields { get; } = fields;

    /// <summary>The indexes of the components in <see cref="KrlExpr.Type"/> (set by the binder).</summary>
    public int[] FieldIndexes { get; set; } = [];
}

/// <summary>The kinds of <see cref="KrlExpr"/>.</summary>
internal enum KrlNode : byte
{
    /// <summary><see cref="KrlOmitted"/>.</summary>
    Omitted,

    /// <summary><see cref="KrlLiteral"/>.</summary>
    Literal,

    /// <summary><see cref="KrlName"/>.</summary>
    Name,

    /// <summary><see cref="KrlMember"/>.</summary>
    Member,

    /// <summary><see cref="KrlIndex"/>.</summary>
    Index,

    /// <summary><see cref="KrlCall"/>.</summary>
    Call,

    /// <summary><see cref="KrlUnary"/>.</summary>
    Unary,

    /// <summary><see cref="KrlBinary"/>.</summary>
    Binary,

    /// <summary><see cref="KrlAggregate"/>.</summary>
    Aggregate,
}

/// <summary>How a <see cref="KrlIndex"/> is read, fixed by the binder.</summary>
internal enum KrlAccess : byte
{
    /// <summary>Through its place (a row of a CHAR array, an element of a component or of an element).</summary>
    Place,

    /// <summary>The whole array (<c>text[]</c>).</summary>
    Whole,

    /// <summary>One signal of an IO array variable (<c>$IN[i]</c>).</summary>
    Signal,

    /// <summary>One element of an array variable or local (<c>slot_v[read_slot, 1]</c>).</summary>
    Element,
}

namespace Machina.Simulation.Rapid;

/// <summary>An expression of a RAPID module; the binder fills in its static type and what its names refer to.</summary>
internal abstract class RapidExpr(int line)
{
    /// <summary>The line where the expression starts.</summary>
    public int Line { get; } = line;

    /// <summary>The static type, set by the binder (null: any, as for an argument of ValToStr).</summary>
    public RapidDataType? Type { get; set; }

    /// <summary>The data a component or element belongs to (<c>rec.x</c>, <c>arr{2}.y</c>: <c>rec</c>, <c>arr</c>); itself otherwise.</summary>
    public RapidExpr Root
    {
        get
        {
            RapidExpr root = this;
            while (root is RapidComponent or RapidIndex)
            {
                root = root is RapidComponent c ? c.Target : ((RapidIndex)root).Target;
            }
            return root;
        }
    }
}

/// <summary>A literal number, string or bool.</summary>
internal sealed class RapidLiteral(int line, object value) : RapidExpr(line)
{
    /// <summary>The value (double, string or bool).</summary>
    public object Value { get; } = value;
}

/// <summary>A name of data: a variable, constant, persistent, parameter or predefined data.</summary>
internal sealed class RapidName(int line, string name) : RapidExpr(line)
{
    /// <summary>The name as written.</summary>
    public string Name { get; } = name;

    /// <summary>The global cell it refers to (null for a local).</summary>
    public RapidCell? Global { get; set; }

    /// <summary>The slot of the local in its routine's frame (when <see cref="Global"/> is null).</summary>
    public int Slot { get; set; } = -1;

    /// <summary>True for a signal read as a value (<c>WaitUntil di1 = 1</c>): it evaluates to the signal's value, not the signal.</summary>
    public bool ReadsSignal { get; set; }
}

/// <summary>A record component, e.g. <c>p.trans.x</c>.</summary>
internal sealed class RapidComponent(int line, RapidExpr target, string name) : RapidExpr(line)
{
    /// <summary>The record.</summary>
    public RapidExpr Target { get; } = target;

    /// <summary>The component's name.</summary>
    public string Name { get; } = name;

    /// <summary>The component's index in the record, set by the binder.</summary>
    public int Index { get; set; } = -1;
}

/// <summary>An array element, e.g. <c>requests{i}</c>.</summary>
internal sealed class RapidIndex(int line, RapidExpr target, RapidExpr[] indices) : RapidExpr(line)
{
    /// <summary>The array.</summary>
    public RapidExpr Target { get; } = target;

    /// <summary>One index per dimension (1-based).</summary>
    public RapidExpr[] Indices { get; } = indices;
}

/// <summary>An aggregate <c>[a, b, …]</c>: a record or array value whose type comes from where it is used.</summary>
internal sealed class RapidAggregate(int line, RapidExpr[] items) : RapidExpr(line)
{
    /// <summary>The components, in order.</summary>
    public RapidExpr[] Items { get; } = items;
}

/// <summary>A unary operator: <c>-</c>, <c>+</c> or <c>NOT</c>.</summary>
internal sealed class RapidUnary(int line, string op, RapidExpr operand) : RapidExpr(line)
{
    /// <summary>The operator, upper case.</summary>
    public string Op { get; } = op;

    /// <summary>True for <c>NOT</c> (a condition negates its operand's value without a box).</summary>
    public bool IsNot { get; } = op == "NOT";

    /// <summary>The operand.</summary>
    public RapidExpr Operand { get; } = operand;
}

/// <summary>A binary operator: arithmetic, <c>DIV</c>, <c>MOD</c>, comparison, <c>AND</c>, <c>OR</c>, <c>XOR</c>.</summary>
internal sealed class RapidBinary(int line, string op, RapidExpr left, RapidExpr right) : RapidExpr(line)
{
    /// <summary>The operator, upper case.</summary>
    public string Op { get; } = op;

    /// <summary>The operator as a code (the machine switches on it instead of comparing strings).</summary>
    public RapidOperator Code { get; } = op switch
    {
        "AND" => RapidOperator.And,
        "OR" => RapidOperator.Or,
        "XOR" => RapidOperator.Xor,
        "=" => RapidOperator.Equal,
        "<>" => RapidOperator.NotEqual,
        "+" => RapidOperator.Add,
        "-" => RapidOperator.Subtract,
        "*" => RapidOperator.Multiply,
        "/" => RapidOperator.Divide,
        "DIV" => RapidOperator.Div,
        "MOD" => RapidOperator.Mod,
        "<" => RapidOperator.Less,
        ">" => RapidOperator.Greater,
        "<=" => RapidOperator.LessOrEqual,
        _ => RapidOperator.GreaterOrEqual,
    };

    /// <summary>The left operand.</summary>
    public RapidExpr Left { get; } = left;

    /// <summary>The right operand.</summary>
    public RapidExpr Right { get; } = right;

    /// <summary>
    /// True when both operands are of a numeric type (num or dnum, not an array; a signal read as a number is not), so that the machine
    /// may take their values as numbers without boxing them; set by the binder.
    /// </summary>
    public bool NumberOperands { get; set; }

    /// <summary>
    /// For a <c>+</c> of two strings, the strings it joins, in order, with those of the concatenations it is made of (<c>"@" + a + " " + b</c>:
    /// four parts), so that the machine makes one string instead of one per operator; null otherwise. Set by the binder.
    /// </summary>
    public RapidExpr[]? Concatenation { get; set; }
}

/// <summary>A function call, e.g. <c>NumToStr(x, 3)</c>.</summary>
internal sealed class RapidCallExpr(int line, string name, RapidArg[] args) : RapidExpr(line)
{
    /// <summary>The function's name.</summary>
    public string Name { get; } = name;

    /// <summary>The arguments.</summary>
    public RapidArg[] Args { get; } = args;

    /// <summary>What the binder found: a built-in or a user routine.</summary>
    public RapidCallTarget? Target { get; set; }
}

/// <summary>An argument: positional, optional (<c>\Name:=value</c>) or a switch (<c>\Name</c>).</summary>
/// <param name="Name">The optional argument's name, or null for a positional one.</param>
/// <param name="Value">The value, or null for a switch.</param>
/// <param name="Line">The argument's line.</param>
internal sealed record RapidArg(string? Name, RapidExpr? Value, int Line);

using System.Globalization;
using System.Runtime.CompilerServices;

namespace Machina.Simulation.Rapid;

/// <summary>Evaluating expressions and storing values.</summary>
internal sealed partial class RapidMachine
{
    /// <summary>Largest string length (RAPID strings hold at most 80 characters).</summary>
    public const int MaxStringLength = 80;

    /// <summary>The value of <paramref name="e"/> (live data for a data reference: copy it before keeping it).</summary>
    public object Evaluate(RapidExpr e, RapidFrame? frame)
    {
        // The commonest nodes first; the rare ones out of line, so that this method stays small.
        switch (e)
        {
            case RapidName n:
            {
                object value = (n.Global ?? frame!.Cells[n.Slot]).Value;
                return n.ReadsSignal || ReferenceEquals(value, Absent) ? SignalOrAbsent(n, value) : value;
            }
            case RapidLiteral l:
                return l.Value;
            case RapidBinary b:
                CheckStack(b.Line);
                return Binary(b, frame);
            case RapidComponent c:
                return ((RapidRecord)Evaluate(c.Target, frame)).Fields[c.Index];
            case RapidCallExpr call:
                CheckStack(call.Line);
                return Call(call.Target!, call.Args, frame, call.Line)!;
            case RapidIndex i:
            {
                var array = (RapidArray)Evaluate(i.Target, frame);
                return array.Items[Offset(array, i, frame)];
            }
            case RapidAggregate a:
                return Aggregate(a, frame);
            case RapidUnary u:
                return Unary(u, frame);
            default:
                throw new InvalidOperationException($"Unknown expression {e.GetType().Name}.");
        }
    }

    /// <summary>The value of a name that reads a signal, or the error of an optional parameter that was not given.</summary>
    private object SignalOrAbsent(RapidName n, object value)
    {
        if (n.ReadsSignal && value is RapidSignalRef signal)
        {
            return SignalValue(signal, n.Line);
        }
        return ReferenceEquals(value, Absent)
            ? throw new RapidRuntimeException(RapidErrorNumbers.NotPres, n.Line, $"the optional parameter '{n.Name}' is not present")
            : value;
    }

    private object Unary(RapidUnary u, RapidFrame? frame)
    {
        CheckStack(u.Line);
        object v = Evaluate(u.Operand, frame);
        return u.Op switch
        {
            "NOT" => RapidBoxes.Bool(!(bool)v),
            "-" when v is RapidRecord p => RapidGeometry.ToPosRecord(-RapidGeometry.ToVector(p)),
            "-" => RapidBoxes.Num(-(double)v),
            _ => v,
        };
    }

    /// <summary>
    /// Stores a copy of <paramref name="value"/> into the data <paramref name="target"/> refers to; with <paramref name="owned"/>
    /// the value was just built (an aggregate) and nothing else refers to it, so it is stored as it is.
    /// </summary>
    public void Store(RapidExpr target, RapidFrame? frame, object value, bool owned = false)
    {
        // A num or bool is its own copy (its box is never mutated) and no string: the commonest stores skip the copy and the tests
        // below, into a name (gap := StrFind(...)), an element (StrToVal into values{n}) or a component alike.
        if (value is double or bool)
        {
            if (target is RapidName number)
            {
                StoreName(number, frame, value);
                return;
            }
        }
        else
        {
            if (!owned && value is RapidRecord from && target is RapidName { Global: null } local && IntoOwnRecord(local, frame!, from))
            {
                return;
            }
            if (!owned)
            {
                value = RapidValues.Copy(value);
            }
            if (value is string s && s.Length > MaxStringLength)
            {
                throw new RapidRuntimeException(RapidErrorNumbers.StringTooLong, target.Line, $"the string is longer than {MaxStringLength} characters");
            }
        }
        switch (target)
        {
            case RapidName n:
                StoreName(n, frame, value);
                break;
            case RapidComponent c:
                ((RapidRecord)Evaluate(c.Target, frame)).Fields[c.Index] = value;
                PartWritten(c.Target, frame);
                break;
            case RapidIndex i:
            {
                var array = (RapidArray)Evaluate(i.Target, frame);
                array.Items[Offset(array, i, frame)] = value;
                PartWritten(i.Target, frame);
                break;
            }
            default:
                throw new RapidRuntimeException(0, target.Line, "only data can be assigned");
        }
    }

    /// <summary>Stores <paramref name="value"/> (a copy already) into the cell <paramref name="n"/> names, counting a write of persistent data.</summary>
    private void StoreName(RapidName n, RapidFrame? frame, object value)
    {
        RapidCell cell = n.Global ?? frame!.Cells[n.Slot];
        cell.Value = value;
        if (cell.Watched)
        {
            PersistentWritten(); // only data an IPers order watches: the others' writes cannot raise an interrupt
        }
    }

    /// <summary>Counts a write of persistent data an IPers order watches and wakes the motion, whose task then looks at its orders.</summary>
    private void PersistentWritten()
    {
        Task.Controller.PersistentWritten();
        Task.Controller.Arm.Wake(); // a task that ordered IPers looks at its data even while its motion runs
    }

    /// <summary>
    /// Assigns a record to a routine's own VAR record datum by copying its components into the record the datum holds, instead of
    /// into a new one (<c>r := requests{i}</c>: a copy of 14 components and its record at every call of our driver's ExecuteNext).
    /// The datum's record is its own: every value a datum is given is a copy or a new aggregate, and the call's values are made
    /// anew at each call. Parameters (whose record may be the caller's, <see cref="IsCallersOwn"/>), data of a caller passed by
    /// reference and global data (read by RWS and other tasks on their own threads) get a new record, as before.
    /// </summary>
    private static bool IntoOwnRecord(RapidName local, RapidFrame frame, RapidRecord from)
    {
        if (local.Slot < frame.Routine.Parameters.Count || !frame.HoldsOwn(local.Slot))
        {
            return false;
        }
        RapidCell cell = frame.Cells[local.Slot];
        if (cell.Storage != RapidStorage.Var || cell.Value is not RapidRecord into || into.Type != from.Type)
        {
            return false;
        }
        RapidValues.CopyInto(into, from);
        cell.Written(); // a local: no other thread reads it, so no odd count while its parts are written
        return true;
    }

    /// <summary>
    /// Counts the write of a component or element in the cell of the data it belongs to (<see cref="RapidCell.Written"/>), and as a
    /// write of persistent data when an IPers order watches that data.
    /// </summary>
    private void PartWritten(RapidExpr data, RapidFrame? frame)
    {
        if (data.Root is RapidName n)
        {
            RapidCell cell = n.Global ?? frame!.Cells[n.Slot];
            cell.Written();
            if (cell.Watched)
            {
                PersistentWritten();
            }
        }
    }

    private int Offset(RapidArray array, RapidIndex i, RapidFrame? frame)
    {
        int offset = 0;
        for (int d = 0; d < i.Indices.Length; d++)
        {
            double index = Number(i.Indices[d], frame);
            if (index != Math.Floor(index) || index < 1 || index > array.Dimensions[d])
            {
                throw new RapidRuntimeException(RapidErrorNumbers.OutOfBounds, i.Line,
                    $"the index {RapidValues.FormatNumber(index)} is outside the array's bounds 1..{array.Dimensions[d]}");
            }
            offset = offset * array.Dimensions[d] + (int)index - 1;
        }
        return offset;
    }

    private object Aggregate(RapidAggregate a, RapidFrame? frame)
    {
        var items = new object[a.Items.Length];
        for (int k = 0; k < items.Length; k++)
        {
            object item = Evaluate(a.Items[k], frame);
            // A nested aggregate is new already; a number, string or bool is its own copy (no call of Copy for it).
            items[k] = item is RapidRecord or RapidArray && a.Items[k] is not RapidAggregate ? RapidValues.Copy(item) : item;
        }
        RapidDataType type = a.Type!.Value;
        return type.Rank > 0 ? new RapidArray([items.Length], items) : new RapidRecord(type.Element, items);
    }

    private object Binary(RapidBinary b, RapidFrame? frame)
    {
        if (b.Concatenation is { } parts)
        {
            return Concatenate(parts, frame);
        }
        RapidOperator op = b.Code;
        if (b.NumberOperands && op > RapidOperator.Xor)
        {
            double x = Number(b.Left, frame), y = Number(b.Right, frame);
            return IsComparison(op) ? RapidBoxes.Bool(Compare(op, x, y)) : RapidBoxes.Num(Arithmetic(b, x, y));
        }
        object l = Evaluate(b.Left, frame);
        switch (op)
        {
            case RapidOperator.And:
                return RapidBoxes.Bool((bool)l && Condition(b.Right, frame));
            case RapidOperator.Or:
                return RapidBoxes.Bool((bool)l || Condition(b.Right, frame));
        }
        object r = Evaluate(b.Right, frame);
        switch (op)
        {
            case RapidOperator.Xor:
                return RapidBoxes.Bool((bool)l ^ (bool)r);
            case RapidOperator.Equal:
                return RapidBoxes.Bool(RapidValues.AreEqual(l, r));
            case RapidOperator.NotEqual:
                return RapidBoxes.Bool(!RapidValues.AreEqual(l, r));
        }
        if (l is double x2 && r is double y2)
        {
            return IsComparison(op) ? RapidBoxes.Bool(Compare(op, x2, y2)) : RapidBoxes.Num(Arithmetic(b, x2, y2));
        }
        if (l is string ls && r is string rs)
        {
            return ls + rs;
        }
        if (l is RapidRecord lp && r is RapidRecord rp)
        {
            Vector sum = op == RapidOperator.Add ? RapidGeometry.ToVector(lp) + RapidGeometry.ToVector(rp) : RapidGeometry.ToVector(lp) - RapidGeometry.ToVector(rp);
            return RapidGeometry.ToPosRecord(sum);
        }
        return l is RapidRecord p ? RapidGeometry.ToPosRecord(RapidGeometry.ToVector(p) * (double)r) : RapidGeometry.ToPosRecord(RapidGeometry.ToVector((RapidRecord)r) * (double)l);
    }

    /// <summary>
    /// Joins the strings of a concatenation (<see cref="RapidBinary.Concatenation"/>), evaluated left to right as the operators would
    /// evaluate them: one new string instead of one per <c>+</c>. (As before, only a string stored or passed on is held to 80 characters.)
    /// </summary>
    private string Concatenate(RapidExpr[] parts, RapidFrame? frame)
    {
        if (parts.Length == 2)
        {
            string first = (string)Evaluate(parts[0], frame);
            return string.Concat(first, (string)Evaluate(parts[1], frame));
        }
        var text = new DefaultInterpolatedStringHandler(0, parts.Length, CultureInfo.InvariantCulture, stackalloc char[MaxStringLength]);
        foreach (RapidExpr part in parts)
        {
            text.AppendLiteral((string)Evaluate(part, frame));
        }
        return text.ToStringAndClear();
    }

    /// <summary>
    /// The value of a num or dnum expression as a number: the operators of an expression whose operands are all numbers (the binder's
    /// <see cref="RapidBinary.NumberOperands"/>) compute without a box for each intermediate result.
    /// </summary>
    internal double Number(RapidExpr e, RapidFrame? frame)
    {
        switch (e)
        {
            case RapidName { ReadsSignal: false } n when (n.Global ?? frame!.Cells[n.Slot]).Value is double value:
                return value; // (an optional parameter not given holds no number: Evaluate raises its error)
            case RapidLiteral l:
                return (double)l.Value;
            case RapidBinary { NumberOperands: true } b when !IsComparison(b.Code):
            {
                CheckStack(b.Line);
                double x = Number(b.Left, frame);
                return Arithmetic(b, x, Number(b.Right, frame));
            }
            default:
                return (double)Evaluate(e, frame);
        }
    }

    /// <summary>The value of a bool expression (a condition of IF, WHILE, AND, OR): comparisons of numbers and AND/OR without boxes.</summary>
    private bool Condition(RapidExpr e, RapidFrame? frame)
    {
        if (e is not RapidBinary b)
        {
            if (e is RapidUnary { IsNot: true } not)
            {
                CheckStack(not.Line);
                return !Condition(not.Operand, frame); // NOT StrToVal(...): no box for the operand's value or the negation
            }
            return (bool)Evaluate(e, frame);
        }
        CheckStack(b.Line);
        switch (b.Code)
        {
            case RapidOperator.And:
                return Condition(b.Left, frame) && Condition(b.Right, frame);
            case RapidOperator.Or:
                return Condition(b.Left, frame) || Condition(b.Right, frame);
        }
        if (b.NumberOperands && IsComparison(b.Code))
        {
            double x = Number(b.Left, frame);
            return Compare(b.Code, x, Number(b.Right, frame));
        }
        return (bool)Binary(b, frame);
    }

    /// <summary>True for <c>=</c>, <c>&lt;&gt;</c>, <c>&lt;</c>, <c>&gt;</c>, <c>&lt;=</c>, <c>&gt;=</c>.</summary>
    private static bool IsComparison(RapidOperator op) => op is RapidOperator.Equal or RapidOperator.NotEqual || op >= RapidOperator.Less;

    /// <summary>A comparison of two numbers (exact, as RAPID compares num data).</summary>
    private static bool Compare(RapidOperator op, double x, double y) => op switch
    {
        RapidOperator.Equal => x == y,
        RapidOperator.NotEqual => x != y,
        RapidOperator.Less => x < y,
        RapidOperator.Greater => x > y,
        RapidOperator.LessOrEqual => x <= y,
        _ => x >= y,
    };

    /// <summary>An arithmetic operator (<c>+ - * / DIV MOD</c>) on two numbers, with RAPID's errors (overflow, division by zero, DIV and MOD of a fraction).</summary>
    private static double Arithmetic(RapidBinary b, double x, double y) => b.Code switch
    {
        RapidOperator.Add => Checked(x + y, b),
        RapidOperator.Subtract => Checked(x - y, b),
        RapidOperator.Multiply => Checked(x * y, b),
        RapidOperator.Divide => y == 0 ? throw DivZero(b) : Checked(x / y, b),
        RapidOperator.Div => y == 0 ? throw DivZero(b) : Math.Truncate(Integer(x, b) / Integer(y, b)),
        _ => y == 0 ? throw DivZero(b) : Integer(x, b) % Integer(y, b),
    };

    /// <summary>The value of a signal read in an expression: 0 or 1 for a digital one, the number of an analog or group one.</summary>
    private object SignalValue(RapidSignalRef signal, int line)
    {
        RapidTwinController c = Task.Controller;
        (string Bank, int Index) s = (signal.Signal is { } name ? c.Signal(name) : null)
            ?? throw new RapidRuntimeException(RapidErrorNumbers.NoAliasIoDef, line, $"the signal variable refers to no signal of the IO configuration");
        return s.Bank[0] == 'd' ? RapidBoxes.Num(c.Io.GetBit(s.Bank, s.Index) ? 1 : 0) : RapidBoxes.Num(c.Io.GetNumber(s.Bank, s.Index));
    }

    private static double Checked(double value, RapidBinary b) => double.IsFinite(value)
        ? value
        : throw new RapidRuntimeException(RapidErrorNumbers.NumOverflow, b.Line, "the result is too large (overflow)");

    private static double Integer(double value, RapidBinary b) => value == Math.Floor(value)
        ? value
        : throw new RapidRuntimeException(RapidErrorNumbers.ArgValErr, b.Line, $"{b.Op} needs integers, not {RapidValues.FormatNumber(value)}");

    private static RapidRuntimeException DivZero(RapidBinary b) => new(RapidErrorNumbers.DivZero, b.Line, "division by zero");
}

namespace Machina.Simulation.Krl;

/// <summary>
/// The compiled form of expressions: at its first evaluation an expression becomes a closure (<see cref="KrlExpr.Compiled"/>)
/// that reads its variable, element or component, or runs its operator, on its compiled operands, without looking at the kinds of
/// the tree's nodes again. What each closure does is what <see cref="EvalTree"/> does for the same node, in the same order, with
/// the same errors: the kinds the twin meets seldom (aggregates, rows and whole arrays read through a place) run the tree walk.
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>The value of <paramref name="expr"/> in <paramref name="frame"/>.</summary>
    public object Eval(KrlExpr expr, object[] frame) => (expr.Compiled ??= Compile(expr))(this, frame);

    /// <summary>The closure that evaluates <paramref name="expr"/> (bound).</summary>
    private static KrlEvaluator Compile(KrlExpr expr)
    {
        switch (expr)
        {
            case KrlLiteral literal:
            {
                object value = literal.Value;
                return (_, _) => value;
            }
            case KrlName { Slot: >= 0 } name:
            {
                int slot = name.Slot;
                return (_, frame) => frame[slot] ?? LocalValue(frame, name);
            }
            case KrlName { Cell: { } cell }:
                return (_, _) => cell.Value;
            case KrlMember member:
            {
                KrlEvaluator target = Compiled(member.Target);
                int field = member.FieldIndex;
                return (machine, frame) => ((KrlStructValue)target(machine, frame)).Values[field];
            }
            case KrlIndex index when index.Each.Length == 0:
                return Compiled(index.Target);
            case KrlIndex { Target: KrlName { Cell.Signals: { } signals } } index when AllGiven(index):
            {
                KrlEvaluator[] indices = CompiledIndices(index);
                int[] sizes = signals.Type.Dimensions;
                int length = signals.Type.Length;
                return (machine, frame) => signals.Get(machine.Flat(index, indices, sizes, length, frame));
            }
            case KrlIndex { Target: KrlName } index when AllGiven(index):
            {
                KrlEvaluator target = Compiled(index.Target);
                KrlEvaluator[] indices = CompiledIndices(index);
                return (machine, frame) =>
                {
                    var array = (KrlArrayValue)target(machine, frame);
                    return array.Items[machine.Flat(index, indices, array.Type.Dimensions, array.Items.Length, frame)];
                };
            }
            case KrlCall call:
                return (machine, frame) =>
                {
                    if (!machine.WritesNothingWatched(call))
                    {
                        machine._writes++;
                    }
                    machine.CheckStack();
                    return machine.Call(call, frame)!;
                };
            case KrlUnary unary:
            {
                KrlEvaluator operand = Compiled(unary.Operand);
                string op = unary.Op;
                return (machine, frame) =>
                {
                    machine.CheckStack();
                    return Unary(op, operand(machine, frame));
                };
            }
            case KrlBinary binary:
            {
                KrlEvaluator left = Compiled(binary.Left), right = Compiled(binary.Right);
                return (machine, frame) =>
                {
                    machine.CheckStack();
                    return Binary(binary, left(machine, frame), right(machine, frame));
                };
            }
            default:
                return (machine, frame) => machine.EvalTree(expr, frame);
        }
    }

    private static KrlEvaluator Compiled(KrlExpr expr) => expr.Compiled ??= Compile(expr);

    /// <summary>True when every index of <paramref name="index"/> is given (<c>a[i, j]</c>, not <c>a[i, ]</c>).</summary>
    private static bool AllGiven(KrlIndex index) => Array.TrueForAll(index.Each, e => e is not null);

    /// <summary>The compiled indices of an element access whose indices are all given.</summary>
    private static KrlEvaluator[] CompiledIndices(KrlIndex index)
    {
        var indices = new KrlEvaluator[index.Each.Length];
        for (int d = 0; d < indices.Length; d++)
        {
            indices[d] = Compiled(index.Each[d]!);
        }
        return indices;
    }

    /// <summary>The element that the compiled <paramref name="indices"/> select in an array of <paramref name="sizes"/> and <paramref name="length"/> elements (as <see cref="Flat(KrlIndex, KrlType, int, object[])"/>).</summary>
    private int Flat(KrlIndex index, KrlEvaluator[] indices, int[] sizes, int length, object[] frame)
    {
        int flat = 0;
        for (int d = 0; d < indices.Length; d++)
        {
            int size = sizes[d] == 0 ? length : sizes[d];
            int i = KrlValues.ToInt(indices[d](this, frame));
            if (i < 1 || i > size)
            {
                throw new KrlRuntimeException($"Array index inadmissible: index {i} of {Describe(index.Target)} is outside 1 to {size}");
            }
            flat = flat * size + (i - 1);
        }
        return flat;
    }
}

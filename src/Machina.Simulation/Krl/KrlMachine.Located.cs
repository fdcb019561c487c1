namespace Machina.Simulation.Krl;

/// <summary>
/// The compiled form of places: at its first write a variable, element or component becomes a closure
/// (<see cref="KrlExpr.Located"/>) that finds where it is stored without looking at the kinds of the tree's nodes again. What each
/// closure does is what <see cref="PlaceTree"/> does for the same node, in the same order, with the same errors: IO arrays, rows
/// and whole arrays run the tree walk.
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>Where <paramref name="expr"/> (a variable, element, row or component) is stored.</summary>
    public KrlPlace Place(KrlExpr expr, object[] frame) => (expr.Located ??= CompileLocator(expr))(this, frame);

    private static KrlLocator Located(KrlExpr expr) => expr.Located ??= CompileLocator(expr);

    /// <summary>The closure that finds where <paramref name="expr"/> (bound) is stored.</summary>
    private static KrlLocator CompileLocator(KrlExpr expr)
    {
        switch (expr)
        {
            case KrlName { Slot: >= 0 } name:
            {
                int slot = name.Slot;
                KrlType type = name.Type;
                return (_, frame) =>
                {
                    frame[slot] ??= KrlValues.Default(type);
                    return new KrlPlace(frame, slot, type);
                };
            }
            case KrlName { Cell: { Signals: null } cell } name:
            {
                object[] box = cell.Box;
                KrlType type = name.Type;
                return (_, _) => new KrlPlace(box, 0, type) { Root = (cell, -1) };
            }
            case KrlMember member:
            {
                KrlLocator target = Located(member.Target);
                int field = member.FieldIndex;
                KrlType type = member.Type;
                return (machine, frame) =>
                {
                    KrlPlace parent = target(machine, frame);
                    var structure = (KrlStructValue)parent.Container[parent.Index];
                    if (structure.Shared)
                    {
                        // A status the EKI_ functions hand out to every caller: the variable gets its own copy before a component changes.
                        structure = structure.Copy();
                        parent.Container[parent.Index] = structure;
                    }
                    return new KrlPlace(structure.Values, field, type) { Root = parent.Root is { } r ? (r.Cell, -1) : null, Structure = structure };
                };
            }
            case KrlIndex { Target: KrlName { Cell.Signals: null } or KrlMember } index when index.Each.Length > 0 && AllGiven(index):
            {
                KrlLocator target = Located(index.Target);
                KrlEvaluator[] indices = CompiledIndices(index);
                KrlType type = index.Type;
                return (machine, frame) =>
                {
                    KrlPlace parent = target(machine, frame);
                    var array = (KrlArrayValue)parent.Container[parent.Index];
                    int flat = machine.Flat(index, indices, array.Type.Dimensions, array.Items.Length, frame);
                    return new KrlPlace(array.Items, flat, type) { Root = parent.Root is { } root ? (root.Cell, flat) : null };
                };
            }
            default:
                return (machine, frame) => machine.PlaceTree(expr, frame);
        }
    }
}

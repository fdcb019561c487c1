namespace Machina.Simulation.Krl;

/// <summary>
/// The compiled form of assignments: at its first run an assignment becomes a closure (<see cref="KrlAssign.Compiled"/>) that
/// evaluates its value and stores it. A local, or a component or element of one, is written without looking at the target's
/// kind again (no interrupt condition can read it, so the conditions are looked at again only when they read locals, call a
/// function or read a computed variable, as <see cref="Assign"/> decides); every other target goes through <see cref="Assign"/>.
/// </summary>
internal sealed partial class KrlMachine
{
    private static Action<KrlMachine, object[]> CompileAssign(KrlAssign assign)
    {
        KrlEvaluator value = Compiled(assign.Value);
        KrlExpr target = assign.Target;
        switch (target)
        {
            case KrlName { Slot: >= 0 } local when assign.Value is KrlCall { Builtin.ReturnsFresh: true }:
            {
                int slot = local.Slot;
                KrlType type = local.Type;
                return (machine, frame) =>
                {
                    object result = value(machine, frame);
                    if (result is KrlStructValue made && made.Type == type)
                    {
                        // A structure the built-in made for this call (ret = EKI_…): the local takes it as it is, the copy would be the same.
                        frame[slot] = made;
                        return;
                    }
                    frame[slot] = KrlConvert.To(type, result, frame[slot]);
                };
            }
            case KrlName { Slot: >= 0 } local:
            {
                int slot = local.Slot;
                KrlType type = local.Type;
                return (machine, frame) =>
                {
                    object result = value(machine, frame);
                    frame[slot] = KrlConvert.To(type, result, frame[slot]);
                };
            }
            case KrlMember when OfLocal(target):
                return (machine, frame) =>
                {
                    object result = value(machine, frame);
                    machine.Place(target, frame).Set(result);
                    if (machine._watchesAll || machine._watchesComputed)
                    {
                        machine._writes++;
                    }
                };
            default:
                return (machine, frame) => machine.Assign(target, value(machine, frame), frame);
        }
    }

    /// <summary>True when <paramref name="place"/> is a component or element of a local (or of a component or element of one).</summary>
    private static bool OfLocal(KrlExpr place) => place switch
    {
        KrlName { Slot: >= 0 } => true,
        KrlIndex index => OfLocal(index.Target),
        KrlMember member => OfLocal(member.Target),
        _ => false,
    };
}

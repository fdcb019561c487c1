namespace Machina.Simulation.Krl;

/// <summary>
/// Components of local structures stored and read as REALs without a box: the driver's <c>target.X = slot_v[read_slot, 1]</c> and
/// <c>pose.X = target.X</c> (twelve an action) went through a boxed double each, which a structure of numbers
/// (<see cref="KrlStructValue"/>) now holds unboxed.
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>
    /// Stores a REAL (or INT) value in a REAL component of a local structure or a REAL element of an array without a box, when
    /// <paramref name="assign"/> is such a store; false (nothing evaluated) otherwise. The value is evaluated first, then the structure found, as <see cref="Assign"/>
    /// does.
    /// </summary>
    private bool AssignRealComponent(KrlAssign assign, object[] frame)
    {
        if (assign.Store is not (KrlStore.LocalMember or KrlStore.Element) || assign.Target.Type.Kind != KrlKind.Real
            || assign.Value.Type.Kind is not (KrlKind.Real or KrlKind.Int))
        {
            return false;
        }
        double value = RealOf(assign.Value, frame);
        if (assign.Store == KrlStore.Element)
        {
            var index = (KrlIndex)assign.Target;
            var array = (KrlArrayValue)Eval(index.Target, frame);
            array.SetReal(Flat(index, array.Type, array.Length, frame), value);
            ElementWritten(index);
            return true;
        }
        var member = (KrlMember)assign.Target;
        KrlStructValue structure = LocalStructure(member, frame);
        structure.SetReal(member.FieldIndex, value);
        LocalComponentWritten(structure, member.FieldIndex);
        return true;
    }

    /// <summary>The local structure whose component <paramref name="member"/> is written: made at its first use, copied when it is a shared status.</summary>
    private static KrlStructValue LocalStructure(KrlMember member, object[] frame)
    {
        var local = (KrlName)member.Target;
        var structure = (KrlStructValue)(frame[local.Slot] ??= KrlValues.Default(local.Type));
        if (structure.Shared)
        {
            structure = structure.Copy();
            frame[local.Slot] = structure;
        }
        return structure;
    }

    /// <summary>After a component of a local structure was written: it was given, and the conditions are looked at again when one reads locals.</summary>
    private void LocalComponentWritten(KrlStructValue structure, int field)
    {
        structure.Give(field);
        if (_watchesAll || _watchesComputed)
        {
            _writes++;
        }
    }

    /// <summary>The INT or REAL component <paramref name="member"/> as a REAL, read without a box.</summary>
    private double RealComponent(KrlMember member, object[] frame) => ((KrlStructValue)Eval(member.Target, frame)).Real(member.FieldIndex);

    /// <summary>The INT or REAL element <paramref name="index"/> of an array variable or local as a REAL, read without a box from a REAL array (the driver's <c>slot_v[read_slot, 1]</c>).</summary>
    private double RealElement(KrlIndex index, object[] frame)
    {
        KrlArrayValue array = ElementArray(index, frame);
        return array.Real(Flat(index, array.Type, array.Length, frame));
    }
}

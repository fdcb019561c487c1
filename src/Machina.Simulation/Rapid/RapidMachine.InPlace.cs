namespace Machina.Simulation.Rapid;

/// <summary>An aggregate assigned to VAR record data written into the record the data hold, instead of a new record.</summary>
internal sealed partial class RapidMachine
{
    /// <summary>The evaluated components of an aggregate written in place; taken while in use (an item's function may assign one too).</summary>
    private object[]? _parts = new object[16];

    /// <summary>
    /// Assigns <paramref name="aggregate"/> (a record's components) to <paramref name="target"/>, VAR data or a component or element
    /// of them, by writing its components into the record the target holds when that is a record of the aggregate's type: our driver's
    /// <c>cursorTarget.trans := [r.p1, r.p2, r.p3]</c> and <c>requests{writeIndex} := [values{1}, …]</c> at every request made a record
    /// and its array each. The components are all evaluated before the first is written (an item may read the target), then the
    /// target is found as <see cref="Store"/> finds it. The value is the one a new record would give: the record is the data's own
    /// (every value data are given is a copy or a new aggregate), and a write of several components counts as one write of its data's
    /// cell, which RWS reads again while it is under way (<see cref="RapidCell.BeginWrite"/>). PERS data, which another task may read
    /// meanwhile on its thread, get a new record as before. False when the target is not such data (nothing evaluated then).
    /// </summary>
    private bool AssignInPlace(RapidExpr target, RapidAggregate aggregate, RapidFrame frame)
    {
        RapidExpr[] items = aggregate.Items;
        if (aggregate.Type is not { Rank: 0 } type || target.Root is not RapidName root || _parts is not { } parts || parts.Length < items.Length)
        {
            return false;
        }
        RapidCell cell = root.Global ?? frame.Cells[root.Slot];
        if (cell.Storage != RapidStorage.Var || cell.Watched || root.ReadsSignal)
        {
            return false;
        }
        _parts = null;
        try
        {
            for (int k = 0; k < items.Length; k++)
            {
                object item = Evaluate(items[k], frame);
                // As Aggregate: a nested aggregate is new already; a number, string or bool is its own copy.
                parts[k] = item is RapidRecord or RapidArray && items[k] is not RapidAggregate ? RapidValues.Copy(item) : item;
            }
            Write(target, cell, frame, parts.AsSpan(0, items.Length), type.Element);
        }
        finally
        {
            parts.AsSpan(0, items.Length).Clear(); // no value is kept alive by the scratch
            _parts = parts;
        }
        return true;
    }

    /// <summary>Writes <paramref name="parts"/> into the record <paramref name="target"/> holds, or a new record of them where it holds none of <paramref name="type"/>.</summary>
    private void Write(RapidExpr target, RapidCell cell, RapidFrame frame, ReadOnlySpan<object> parts, RapidType type)
    {
        object[] holder;
        int index;
        switch (target)
        {
            case RapidComponent c:
                holder = ((RapidRecord)Evaluate(c.Target, frame)).Fields;
                index = c.Index;
                break;
            case RapidIndex i:
            {
                var array = (RapidArray)Evaluate(i.Target, frame);
                holder = array.Items;
                index = Offset(array, i, frame);
                break;
            }
            default:
                if (cell.Value is RapidRecord own && own.Type == type && own.Fields.Length == parts.Length)
                {
                    WriteParts(own, cell, parts);
                }
                else
                {
                    cell.Value = new RapidRecord(type, parts.ToArray());
                }
                return;
        }
        if (holder[index] is RapidRecord held && held.Type == type && held.Fields.Length == parts.Length)
        {
            WriteParts(held, cell, parts);
            return;
        }
        holder[index] = new RapidRecord(type, parts.ToArray());
        cell.Written();
    }

    /// <summary>Copies <paramref name="parts"/> into <paramref name="record"/>, one write of <paramref name="cell"/>'s data.</summary>
    private static void WriteParts(RapidRecord record, RapidCell cell, ReadOnlySpan<object> parts)
    {
        cell.BeginWrite();
        parts.CopyTo(record.Fields);
        cell.EndWrite();
    }
}

namespace Machina.Simulation.Rapid;

/// <summary>
/// A value as it was read from data: the cell of the data (or of the data it is a part of), the value object, and the cell's write
/// count taken before the read (<see cref="RapidCell.Version"/>). Two marks that are equal, of a cell, are of the same value unchanged,
/// its parts included: the cell holds the same object and counts no write between them. (The count is taken first: a write during
/// the read makes the next read's count differ, never the same.)
/// </summary>
internal readonly struct RapidCellMark
{
    private readonly RapidCell? _cell;
    private readonly object? _value;
    private readonly long _version;

    /// <summary>Marks <paramref name="value"/>, read from <paramref name="cell"/> (null: no data's value, a function's result) when it counted <paramref name="version"/> writes.</summary>
    public RapidCellMark(RapidCell? cell, object value, long version)
    {
        _cell = cell;
        _value = value;
        _version = version;
    }

    /// <summary>True when both marks are of one cell's same value with no write between them.</summary>
    public bool Same(in RapidCellMark other) =>
        _cell is not null && ReferenceEquals(_cell, other._cell) && ReferenceEquals(_value, other._value) && _version == other._version;
}

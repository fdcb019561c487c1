using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// <c>RapidValues.Identical</c>, which lets a motion keep its copy of the tooldata and wobjdata while they are the same to the bit
/// (issue 45; tested one value at a time since): numbers by their bits, records by type and component, arrays by their sizes and
/// elements, a value never identical to a value of another kind, and data that are not values by reference.
/// </summary>
public class RapidValuesIdenticalTests
{
    private static readonly (string Pair, object A, object B, bool Identical)[] Pairs =
    [
        ("same number", 1.5, 1.5, true),
        ("0 and -0", 0.0, -0.0, false),
        ("a NaN and itself", double.NaN, double.NaN, true),
        ("different numbers", 1.0, 2.0, false),
        ("a number and a bool", 1.0, true, false),
        ("a bool and a number", true, 1.0, false),
        ("same bools", false, false, true),
        ("different bools", true, false, false),
        ("same text", "tool0", new string("tool0".ToCharArray()), true),
        ("text of another case", "tool0", "TOOL0", false),
        ("a text and a number", "1", 1.0, false),
        ("same records", Pose(Pos(1, 2, 3)), Pose(Pos(1, 2, 3)), true),
        ("a nested component differs", Pose(Pos(1, 2, 3)), Pose(Pos(1, 2, 3.0000000000000004)), false),
        ("records of another type", Pos(1, 0, 0), new RapidRecord(RapidTypes.Orient, [1.0, 0.0, 0.0]), false),
        ("a record and a number", Pos(1, 2, 3), 1.0, false),
        ("same arrays", new RapidArray([2], [1.0, 2.0]), new RapidArray([2], [1.0, 2.0]), true),
        ("arrays of other sizes", new RapidArray([2, 1], [1.0, 2.0]), new RapidArray([1, 2], [1.0, 2.0]), false),
        ("an array and a record", new RapidArray([3], [1.0, 2.0, 3.0]), Pos(1, 2, 3), false),
    ];

    private static RapidRecord Pos(double x, double y, double z) => new(RapidTypes.Pos, [x, y, z]);

    private static RapidRecord Pose(RapidRecord trans) => new(RapidTypes.PoseType, [trans, new RapidRecord(RapidTypes.Orient, [1.0, 0.0, 0.0, 0.0])]);

    [Fact]
    public void Identical_ComparesValuesToTheBit()
    {
        foreach ((string pair, object a, object b, bool identical) in Pairs)
        {
            Assert.True(identical == RapidValues.Identical(a, b), pair);
            Assert.True(identical == RapidValues.Identical(b, a), pair + ", turned round");
        }
    }

    [Fact]
    public void DataThatAreNotValues_AreIdenticalOnlyToThemselves()
    {
        var socket = new RapidSocketDevice();

        Assert.True(RapidValues.Identical(socket, socket));
        Assert.False(RapidValues.Identical(socket, new RapidSocketDevice()));
        Assert.False(RapidValues.Identical(socket, 1.0));
        Assert.False(RapidValues.Identical(1.0, socket));
    }
}

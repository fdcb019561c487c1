using System.Text;

namespace Machina.Tests.Brands.Abb;

/// <summary>The one-array move line writes exactly what the writer's builder path writes, and leaves huge coordinates to it.</summary>
public class RapidMoveLineTests
{
    [Fact]
    public void TryWrite_ChangingTargetSettingsAndComments_SameTextAsBuilder()
    {
        var line = new RapidMoveLine();
        var sink = new ListLineSink();
        Rotation flat = Rotation.Identity;
        Rotation turned = new(new Vector(0, 0, 1), 90);
        var move = new ActionTranslation(new Vector(-7.25, 0.001, 1e-7), true);
        var turn = new ActionRotation(new Vector(0, 0, 1), 90, true);
        var turnTo = new ActionRotation(turned, false);
        (Vector P, Rotation R, AbbConfiguration? C, string Speed, string Zone, string Tool, RobotAction Action, bool Human)[] moves =
        [
            (new Vector(400, 300, 500), flat, null, "vel20", "z5", "Tool0", move, true),
            (new Vector(401.5, -0.25, 500), flat, null, "vel20", "z5", "Tool0", move, true),
            (new Vector(401.5, -0.25, 500), turned, null, "vel20", "z5", "Tool0", turn, true),
            (new Vector(-0.0004, 2, 3), turned, null, "vel100", "z5", "Tool0", move, true),
            (new Vector(1, 2, 3), turned, null, "vel100", "fine", "Tool0", move, true),
            (new Vector(1, 2, 3), turned, new AbbConfiguration(0, -1, 2, 1), "vel100", "fine", "Pen", move, true),
            (new Vector(7, 8, 9), flat, null, "vel100", "fine", "Pen", move, false),
            (new Vector(7, 8, 9), flat, null, "vel100", "fine", "Pen", move, false),
            (new Vector(7, 8, 9), turned, null, "vel100", "fine", "Pen", turnTo, true),
            (new Vector(7, 8, 9), flat, null, "vel100", "fine", "Pen", turn, true),
        ];
        var expected = new List<string>();
        foreach (var m in moves)
        {
            Assert.True(line.TryWrite(sink, "    MoveL ", m.P, m.R, null, null, m.C, m.Speed, m.Zone, m.Tool, m.Action, m.Human));
            var sb = new StringBuilder("    MoveL ").RobTarget(m.P, m.R, null, null, m.C).Append(", ").Append(m.Speed).Append(", ").Append(m.Zone)
                .Append(", ").Append(m.Tool).Append("\\WObj:=WObj0;");
            expected.Add(m.Human ? sb.Append("  ! [").AppendDescription(m.Action).Append(']').ToString() : sb.ToString());
        }
        Assert.Equal(expected, sink.Lines.ToList());
        Assert.Equal("    MoveL [[0, 2, 3], [0.7071, 0, 0, 0.7071], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, z5, Tool0\\WObj:=WObj0;  ! [Move [-7.25, 0.001, 0] mm]", sink.Lines[3]);
        Assert.Equal("    MoveL [[7, 8, 9], [1, 0, 0, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, fine, Pen\\WObj:=WObj0;", sink.Lines[7]);
        Assert.Equal("    MoveL [[7, 8, 9], [0.7071, 0, 0, 0.7071], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, fine, Pen\\WObj:=WObj0;  ! [Rotate to [[0, 1, 0], [-1, 0, 0], [0, 0, 1]]]", sink.Lines[8]);
        Assert.Equal("    MoveL [[7, 8, 9], [1, 0, 0, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel100, fine, Pen\\WObj:=WObj0;  ! [Rotate 90 deg around [0, 0, 1]]", sink.Lines[9]);
    }

    [Fact]
    public void TryWrite_CoordinateTooLargeForTheFastDigits_WritesNothing()
    {
        var line = new RapidMoveLine();
        var sink = new ListLineSink();
        Assert.False(line.TryWrite(sink, "    MoveL ", new Vector(1, 2e13, 3), Rotation.Identity, null, null, null, "v", "z", "t", new ActionTranslation(new Vector(1, 0, 0), true), true));
        Assert.Empty(sink.Lines);
    }
}

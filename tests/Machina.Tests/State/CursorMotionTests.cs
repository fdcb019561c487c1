namespace Machina.Tests.State;

/// <summary>How motions change the pose (spec §6.2), with hand-computed poses. The default tool points down: 180° about world Y.</summary>
public class CursorMotionTests
{
    private static readonly Vector Down = new(0, 0, -1);

    [Fact]
    public void Create_NewRobot_HasTheInitialState()
    {
        RobotState s = Robot.Create("Fresh", RobotType.UR).GetCurrentState();

        Assert.Null(s.Position);
        Assert.Null(s.Axes);
        Assert.Equal(Rotation.FlippedAroundY, s.Rotation);
        Assert.Equal(new Settings(20, 30, 5, MotionType.Linear, ReferenceCS.World, 0), s.Settings);
        Assert.Null(s.Tool);
        Assert.Empty(s.DefinedTools);
        Assert.Null(s.ExternalAxesCartesian);
        Assert.Null(s.ArmAngle);
        Assert.Equal((0.0, 0.0, 0.0), (s.ExtruderTemperature, s.BedTemperature, s.ChamberTemperature));
        Assert.False(s.IsExtruding);
        Assert.Equal(0, s.SettingsDepth);
        Assert.Null(s.LastAction);
    }

    [Fact]
    public void Move_World_AddsTheOffset()
    {
        var bot = PoseAssert.AtFlipped(400, 300, 500);
        bot.Move(0, 0, 250);

        Assert.Equal(new Point(400, 300, 750), bot.GetCurrentPosition());
        Assert.Equal(Rotation.FlippedAroundY, bot.GetCurrentRotation());
    }

    [Fact]
    public void Move_Local_OffsetIsInTheToolFrame()
    {
        var bot = PoseAssert.AtFlipped(400, 300, 500);
        bot.Coordinates(ReferenceCS.Local);
        bot.Move(10, 0, 5); // tool X = world −X, tool Z = world −Z

        PoseAssert.Near(new Vector(390, 300, 495), bot.GetCurrentPosition());
    }

    [Fact]
    public void MoveTo_KeepsTheOrientation()
    {
        var bot = PoseAssert.AtFlipped(1, 2, 3);
        bot.Rotate(0, 0, 1, 30);
        Rotation before = bot.GetCurrentRotation()!.Value;
        bot.MoveTo(-5, 6, 7);

        Assert.Equal(new Point(-5, 6, 7), bot.GetCurrentPosition());
        Assert.Equal(before, bot.GetCurrentRotation());
    }

    [Fact]
    public void Rotate_World_PreMultiplies()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Rotate(0, 0, 1, 90); // Rz(90)·Ry(180): tool X −X → −Y

        PoseAssert.Axes(new Vector(0, -1, 0), Down, bot.GetCurrentRotation());
        Assert.Equal(new Point(100, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void Rotate_Local_PostMultiplies()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Coordinates("local");
        bot.Rotate(0, 0, 1, 90); // Ry(180)·Rz(90): tool X = Ry(180)·(+Y) = +Y

        PoseAssert.Axes(new Vector(0, 1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void Rotate_LocalAboutToolX_TiltsTheToolZ()
    {
        var bot = PoseAssert.AtFlipped(0, 0, 0);
        bot.Coordinates(ReferenceCS.Local);
        bot.Rotate(Vector.XAxis, 90); // tool Z (down) turns towards −(tool Y) = −Y

        PoseAssert.Axes(new Vector(-1, 0, 0), new Vector(0, -1, 0), bot.GetCurrentRotation());
    }

    [Fact]
    public void RotateTo_SetsTheOrientationAndKeepsThePosition()
    {
        var bot = PoseAssert.AtFlipped(1, 2, 3);
        bot.RotateTo(0, 1, 0, -1, 0, 0); // X→+Y, Y→−X, so Z = +Z

        PoseAssert.Axes(new Vector(0, 1, 0), new Vector(0, 0, 1), bot.GetCurrentRotation());
        Assert.Equal(new Point(1, 2, 3), bot.GetCurrentPosition());
    }

    [Fact]
    public void Transform_World_MovesThenRotatesInWorld()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Transform(new Vector(10, 0, 0), Rotation.FromAxisAngle(Vector.ZAxis, 90));

        PoseAssert.Near(new Vector(110, 0, 0), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(0, -1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void Transform_WorldRotateFirst_IsTheSameAsTranslationFirst()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Transform(Rotation.FromAxisAngle(Vector.ZAxis, 90), new Vector(10, 0, 0));

        PoseAssert.Near(new Vector(110, 0, 0), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(0, -1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void Transform_LocalTranslationFirst_MovesAlongTheOldToolX()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Coordinates(ReferenceCS.Local);
        bot.Transform(new Vector(10, 0, 0), Rotation.FromAxisAngle(Vector.ZAxis, 90));

        PoseAssert.Near(new Vector(90, 0, 0), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(0, 1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void Transform_LocalRotateFirst_MovesAlongTheNewToolX()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Coordinates(ReferenceCS.Local);
        bot.Transform(Rotation.FromAxisAngle(Vector.ZAxis, 90), new Vector(10, 0, 0));

        PoseAssert.Near(new Vector(100, 10, 0), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(0, 1, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void TransformTo_FromUnknownPose_SetsBoth()
    {
        var bot = Robot.Create("T", RobotType.KUKA);
        bot.TransformTo(300, 300, 300, -1, 0, 0, 0, 1, 0);

        Assert.Equal(new Point(300, 300, 300), bot.GetCurrentPosition());
        PoseAssert.Axes(new Vector(-1, 0, 0), Down, bot.GetCurrentRotation());
    }

    [Fact]
    public void AxesTo_ForgetsThePose_AndOnlyTransformToOrAxesWork()
    {
        var bot = PoseAssert.AtFlipped(400, 300, 500);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        Assert.Null(bot.GetCurrentPosition());
        Assert.Null(bot.GetCurrentRotation());
        var moveTo = Assert.Throws<ActionRefusedException>(() => bot.MoveTo(1, 2, 3));
        Assert.Contains("orientation is not known", moveTo.Message);
        var rotateTo = Assert.Throws<ActionRefusedException>(() => bot.RotateTo(1, 0, 0, 0, 1, 0));
        Assert.Contains("position is not known", rotateTo.Message);
        Assert.Throws<ActionRefusedException>(() => bot.Move(1, 0, 0));
        Assert.Throws<ActionRefusedException>(() => bot.Rotate(0, 0, 1, 5));

        bot.Axes(10, 0, 0, 0, 0, -5);
        Assert.Equal(new Joints(10, 0, 0, 0, 90, -5), bot.GetCurrentAxes());
        bot.TransformTo(new Vector(1, 2, 3), Rotation.Identity);
        Assert.Equal(new Point(1, 2, 3), bot.GetCurrentPosition());
        Assert.Null(bot.GetCurrentAxes());
    }

    [Fact]
    public void Axes_AfterCartesianMotion_IsRefused()
    {
        var bot = PoseAssert.AtFlipped(1, 2, 3);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.Axes(1, 0, 0, 0, 0, 0));

        Assert.Equal("Cannot apply \"Axes(1,0,0,0,0,0);\": the joint angles are not known yet (the last motion was Cartesian); use AxesTo before relative Axes.", ex.Message);
    }

    [Fact]
    public void Move_BeforeAnyAbsoluteMotion_IsRefusedWithoutConsumingAnId()
    {
        var bot = Robot.Create("R", RobotType.ABB);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.Move(0, 0, 10));
        bot.MoveTo(0, 0, 0);

        Assert.Equal("Cannot apply \"Move(0,0,10);\": the current position of the tool is not known yet; start with MoveTo, TransformTo or AxesTo before relative motions.", ex.Message);
        Assert.Equal(new ActionTranslation(new Vector(0, 0, 10), true), ex.Action);
        Assert.Equal(-1, ex.Action.Id);
        Assert.Equal(1, Assert.Single(bot.GetProgramActions()).Id);
    }

    [Fact]
    public void ArcMotionTo_QuarterCircle_EndsAtTheEndKeepingOrientation()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        double h = 100 / Math.Sqrt(2);
        bot.ArcMotionTo(h, h, 0, 0, 100, 0);

        Assert.Equal(new Point(0, 100, 0), bot.GetCurrentPosition());
        Assert.Equal(Rotation.FlippedAroundY, bot.GetCurrentRotation());
    }

    [Fact]
    public void ArcMotion_RelativeLocal_UsesTheToolFrameForBothPoints()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        bot.Coordinates(ReferenceCS.Local);
        bot.ArcMotion(10, 10, 0, 20, 0, 0); // tool X = −X: end at (80, 0, 0)

        PoseAssert.Near(new Vector(80, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void ArcMotionTo_CollinearPoints_IsRefused()
    {
        var bot = PoseAssert.AtFlipped(0, 0, 0);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.ArcMotionTo(1, 0, 0, 2, 0, 0));

        Assert.Contains("on one line or coincide", ex.Reason);
        Assert.Equal(new Point(0, 0, 0), bot.GetCurrentPosition());
    }

    [Fact]
    public void ArcMotionTo_Planes_EndsWithTheEndOrientation()
    {
        var bot = PoseAssert.AtFlipped(100, 0, 0);
        double h = 100 / Math.Sqrt(2);
        Rotation end = Rotation.FromAxisAngle(Vector.ZAxis, 90);
        bot.ArcMotionTo(new Plane(new Vector(h, h, 0), Rotation.Identity), new Plane(new Vector(0, 100, 0), end));

        Assert.Equal(end, bot.GetCurrentRotation());
    }
}

using Machina.Tests.Geometry;

namespace Machina.Tests.Actions;

/// <summary>Round trip ToInstruction → Instructions.Parse for the edge cases the general round-trip tests do not reach.</summary>
public class ActionRoundTripEdgeTests
{
    private static RobotAction ParseOne(string text) => Assert.Single(Instructions.Parse(text));

    [Fact]
    public void RelativeIdentityRotation_WritesAParseableInstruction()
    {
        var action = new ActionRotation(Rotation.Identity, true);

        Assert.Equal("Rotate(0,0,1,0);", action.ToInstruction());
        Assert.Equal(action, ParseOne(action.ToInstruction()));
    }

    [Fact]
    public void RelativeTransformWithoutTurn_WritesAParseableInstruction()
    {
        var action = new ActionTransformation(new Vector(1, 2, 3), Rotation.Identity, true, false);

        Assert.Equal("Transform(1,2,3,0,0,1,0,False);", action.ToInstruction());
        Assert.Equal(action, ParseOne(action.ToInstruction()));
    }

    [Fact]
    public void Robot_RotateByIdentity_CanBeRepeatedWithDo()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);
        bot.Rotate(Rotation.Identity);

        bot.Do(bot.GetProgramActions()[^1].ToInstruction());

        Assert.Equal(3, bot.GetProgramActions().Count);
        Assert.Equal(bot.GetProgramActions()[1], bot.GetProgramActions()[2]);
    }

    [Fact]
    public void AbsoluteTransformGivenRotationFirst_RoundTripsToAnEqualAction()
    {
        // TransformTo(rotation, position) and TransformTo(position, rotation) reach the same pose; the order only matters for relative ones.
        var action = new ActionTransformation(new Vector(1, 2, 3), Rotation.FromAxisAngle(1, 1, 1, 180), false, false);

        RobotAction parsed = ParseOne(action.ToInstruction());

        Assert.Equal(action, parsed);
        Assert.Equal(action.GetHashCode(), parsed.GetHashCode());
        Assert.NotEqual<RobotAction>(new ActionTransformation(new Vector(1, 2, 3), Rotation.Identity, true, false),
            new ActionTransformation(new Vector(1, 2, 3), Rotation.Identity, true, true));
    }
}

/// <summary>Short but non-zero rotation axes are directions, as in Rotation.FromAxisAngle.</summary>
public class ShortAxisTests
{
    [Fact]
    public void Rotate_AboutAShortAxis_TurnsLikeTheUnitAxis()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MoveTo(0, 0, 0);

        bot.Rotate(1e-7, 0, 0, 90);

        Oracle.SameRotation(Rotation.FromAxisAngle(Vector.XAxis, 90) * Rotation.FlippedAroundY, bot.GetCurrentRotation()!.Value, 1e-12);
        Assert.Equal("Rotate(1,0,0,90);", bot.GetProgramActions()[^1].ToInstruction());
    }

    [Fact]
    public void Rotate_AboutAZeroAxis_IsRefusedNamingTheAxis()
    {
        var ex = Assert.Throws<ArgumentException>(() => new ActionRotation(new Vector(0, 1e-10, 0), 90, true));

        Assert.Equal("axis", ex.ParamName);
        Assert.StartsWith("The rotation axis (0, 1E-10, 0) has no direction; give one such as (0, 0, 1).", ex.Message, StringComparison.Ordinal);
    }
}

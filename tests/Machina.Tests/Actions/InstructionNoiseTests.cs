namespace Machina.Tests.Actions;

/// <summary>
/// Instruction texts derived from a rotation carry no floating-point noise: axis components within 1e-15 of 0 or ±1 are
/// written as 0 or ±1, and the text still reads back to an equal action.
/// </summary>
public class InstructionNoiseTests
{
    public static TheoryData<RobotAction, string> Clean => new()
    {
        { new ActionRotation(Rotation.FromAxes(new Vector(0, 0, -1), new Vector(0, 1, 0)), relative: false), "RotateTo(0,0,-1,0,1,0);" },
        { new ActionRotation(Rotation.FromAxes(new Vector(0, 1, 0), new Vector(-1, 0, 0)), relative: false), "RotateTo(0,1,0,-1,0,0);" },
        { new ActionRotation(Rotation.FromAxisAngle(new Vector(0, 1, 0), 90), relative: true), "Rotate(0,1,0,90);" },
        { new ActionTransformation(new Vector(400, 0, 300), Rotation.FromAxes(new Vector(0, 0, -1), new Vector(0, 1, 0)), relative: false, translationFirst: true), "TransformTo(400,0,300,0,0,-1,0,1,0);" },
        { new ActionTransformation(new Vector(1, 2, 3), Rotation.FromAxisAngle(new Vector(0, 0, 1), 90), relative: true, translationFirst: true), "Transform(1,2,3,0,0,1,90);" },
        { new ActionDefineTool(Tool.Create("pen", new Vector(0, 0, 100), Rotation.FromAxes(new Vector(0, 0, -1), new Vector(0, 1, 0)), 1, new Vector(0, 0, 50))), "DefineTool(\"pen\",0,0,100,0,0,-1,0,1,0,1,0,0,50);" },
    };

    [Theory]
    [MemberData(nameof(Clean))]
    public void ToInstruction_RotationWithNoise_WritesCleanAxesThatReadBackEqual(RobotAction action, string expected)
    {
        Assert.Equal(expected, action.ToInstruction());
        Assert.Equal(action, Assert.Single(Instructions.Parse(expected)));
    }

    [Fact]
    public void MachinaProgram_RotateToDown_HasNoNoise()
    {
        Robot bot = Robot.Create("Clean", RobotType.ABB);
        bot.MoveTo(400, 0, 300);
        bot.RotateTo(0, 0, -1, 0, 1, 0);

        string text = bot.Compile(RobotType.MACHINA).MainFile.ToText();

        Assert.Contains("RotateTo(0,0,-1,0,1,0);", text, StringComparison.Ordinal);
        Assert.DoesNotContain("E-1", text, StringComparison.Ordinal);
    }
}

using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>Every URScript golden file runs on the twin controller and ends where the library's cursor says, step by step.</summary>
public class UrScriptGoldenTwinTests(ITestOutputHelper output)
{
    public static TheoryData<string, string?> Files => new()
    {
        { "HelloRobot", null }, { "HelloRobot", "declared" }, { "HelloRobot", "plain" }, { "HelloRobot", "declared-plain" },
        { "SquarePushPop", null }, { "SquarePushPop", "declared" }, { "Rotations", null }, { "Rotations", "declared" },
        { "JointsToolsIO", null }, { "JointsToolsIO", "declared" },
    };

    [Theory]
    [MemberData(nameof(Files))]
    public void GoldenFile_RunsOnTheTwin_AndMatchesTheCursorStepByStep(string name, string? variant)
    {
        string path = Path.Combine(AppContext.BaseDirectory, "Golden", "UR", name + (variant is null ? "" : "." + variant) + ".script");
        string script = File.ReadAllText(path);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue(name, RobotType.UR).GetProgramActions();

        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(script, actions);

        output.WriteLine(result.ToText());
        Assert.True(result.Passed, result.ToText());
        Assert.Equal(UrProgramState.Finished, result.State);
        Assert.Equal(actions.Count(a => a is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes
            || (a is ActionIODigital d && d.IsDigit)), result.Steps.Count);
    }

    /// <summary>
    /// Print3D prints at 50–70 mm from the base axis with the tool pointing down: a UR5e cannot get its wrist there (the shoulder
    /// offset keeps the wrist at least 133 mm from axis 1), so the controller stops at the first move, as a real one would.
    /// </summary>
    [Theory]
    [InlineData(null, 12)]
    [InlineData("declared", 25)]
    public void Print3D_OnAUR5e_StopsAtItsFirstMoveWithTheControllersMessage(string? variant, int line)
    {
        string script = File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "Golden", "UR", "Print3D" + (variant is null ? "" : "." + variant) + ".script"));
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("Print3D", RobotType.UR).GetProgramActions();

        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(script, actions);

        Assert.Equal(UrProgramState.Failed, result.State);
        Assert.Equal($"Runtime error: line {line}: movep: no inverse kinematics solution: the target pose is out of reach", result.Error);
        Assert.All(result.Steps, s => Assert.Equal("the program stopped before this step", s.Problem));
        Assert.Equal(12, result.Steps.Count);
    }

    [Fact]
    public void EditedScript_ThatMovesElsewhere_IsReportedAtItsStep()
    {
        string script = File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "Golden", "UR", "SquarePushPop.script"))
            .Replace("movep(p[0.35,0,0.3,", "movep(p[0.35,0.001,0.3,", StringComparison.Ordinal);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("SquarePushPop", RobotType.UR).GetProgramActions();

        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(script, actions);

        Assert.False(result.Passed);
        TwinVerifyStep step = Assert.Single(result.Steps, s => s.Problem is not null);
        Assert.Equal(2, step.Index);
        Assert.Equal("the TCP is 1 mm away", step.Problem);
    }

    [Fact]
    public void Script_WithAnUnreachableTarget_StopsThereWithTheControllersMessage()
    {
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("SquarePushPop", RobotType.UR).GetProgramActions();
        string script = File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "Golden", "UR", "SquarePushPop.script"))
            .Replace("movep(p[0.35,0,0.3,", "movep(p[1.35,0,0.3,", StringComparison.Ordinal);

        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify(script, actions);

        Assert.Equal(UrProgramState.Failed, result.State);
        Assert.Equal("Runtime error: line 14: movep: no inverse kinematics solution: the target pose is out of reach", result.Error);
        Assert.Equal("the program stopped before this step", result.Steps[1].Problem);
    }
}

using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Tests.Support;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>Every RAPID golden program loads on the RAPID twin, runs main and ends where the library's cursor says, step by step.</summary>
public class RapidGoldenTwinTests(ITestOutputHelper output)
{
    public static TheoryData<string, string?> Files => new()
    {
        { "SquarePushPop", null }, { "SquarePushPop", "declared" }, { "Rotations", null }, { "Rotations", "declared" },
        { "JointsToolsIO", null }, { "JointsToolsIO", "declared" }, { "Print3D", null }, { "Print3D", "declared" },
    };

    private static (string, string)[] Modules(string name, string? variant)
    {
        // Each variant's .pgf names the module "NAME.mod" (the file name a compiled program has); the golden variants are stored beside it.
        string mod = Path.Combine(AppContext.BaseDirectory, "Golden", "ABB", name + (variant is null ? "" : "." + variant) + ".mod");
        return [(name + ".mod", File.ReadAllText(mod))];
    }

    [Theory]
    [MemberData(nameof(Files))]
    public void GoldenProgram_RunsOnTheTwin_AndMatchesTheCursorStepByStep(string name, string? variant)
    {
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue(name, RobotType.ABB).GetProgramActions();

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(Modules(name, variant), actions);

        output.WriteLine(result.ToText());
        Assert.True(result.Passed, result.ToText());
        Assert.Equal(RapidProgramState.Finished, result.State);
        Assert.Equal(actions.Count(a => a is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes
            || (a is ActionIODigital d && !d.IsDigit) || (a is ActionIOAnalog an && !an.IsDigit)), result.Steps.Count);
    }

    /// <summary>HelloRobot lifts the tool to z = 750 mm at 500 mm from axis 1: beyond an IRB 120's 580 mm reach, so its third move stops the task.</summary>
    [Theory]
    [InlineData(null, 18)]
    [InlineData("plain", 17)]
    [InlineData("declared", 23)]
    [InlineData("declared-plain", 22)]
    public void HelloRobot_OnAnIrb120_StopsAtItsThirdMoveWithTheEventLogMessage(string? variant, int line)
    {
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("HelloRobot", RobotType.ABB).GetProgramActions();

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(Modules("HelloRobot", variant), actions);

        Assert.Equal(RapidProgramState.Failed, result.State);
        Assert.Equal($"50050 Position outside reach: no inverse kinematics solution: the target pose is out of reach (line {line}, task T_ROB1)", result.Error);
        Assert.Equal([null, null, "the program stopped before this step", "the program stopped before this step"], result.Steps.Select(s => s.Problem));
    }

    [Theory]
    [InlineData(null)]
    [InlineData("plain")]
    [InlineData("declared")]
    [InlineData("declared-plain")]
    public void HelloRobot_OnAnIrb1200_RunsToItsEnd_AndMatchesTheCursor(string? variant)
    {
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("HelloRobot", RobotType.ABB).GetProgramActions();
        var options = new RapidTwinOptions { Model = RobotModels.Get("IRB 1200-5/0.9") };

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(Modules("HelloRobot", variant), actions, options);

        output.WriteLine(result.ToText());
        Assert.True(result.Passed, result.ToText());
        Assert.Equal(4, result.Steps.Count);
    }

    [Fact]
    public void EditedProgram_ThatMovesElsewhere_IsReportedAtItsStep()
    {
        (string Name, string Text)[] modules = Modules("SquarePushPop", null);
        modules[0].Text = modules[0].Text.Replace("MoveL [[350, 0, 300]", "MoveL [[350, 1, 300]", StringComparison.Ordinal);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("SquarePushPop", RobotType.ABB).GetProgramActions();

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(modules, actions);

        Assert.False(result.Passed);
        TwinVerifyStep step = Assert.Single(result.Steps, s => s.Problem is not null);
        Assert.Equal(2, step.Index);
        Assert.Equal("the TCP is 1 mm away", step.Problem);
    }

    [Fact]
    public void Program_WithAnUnreachableTarget_StopsThereWithTheEventLogMessage()
    {
        (string Name, string Text)[] modules = Modules("SquarePushPop", null);
        modules[0].Text = modules[0].Text.Replace("MoveL [[350, 0, 300]", "MoveL [[1350, 0, 300]", StringComparison.Ordinal);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue("SquarePushPop", RobotType.ABB).GetProgramActions();

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify(modules, actions);

        Assert.Equal(RapidProgramState.Failed, result.State);
        int line = modules[0].Text.Split('\n').ToList().FindIndex(l => l.Contains("[[1350, 0, 300]", StringComparison.Ordinal)) + 1;
        Assert.Equal($"50050 Position outside reach: no inverse kinematics solution: the target pose is out of reach (line {line}, task T_ROB1)", result.Error);
        Assert.Equal("the program stopped before this step", result.Steps[1].Problem);
    }
}

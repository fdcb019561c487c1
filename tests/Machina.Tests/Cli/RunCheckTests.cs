using Machina.Cli;
using Machina.Cli.Commands;
using Machina.Cli.Programs;

namespace Machina.Tests.Cli;

/// <summary>Issue 21 §1: <c>machina run</c> checks the whole program before the first action is sent, and stops with the line of an action the controller could not run.</summary>
public class RunCheckTests
{
    [Fact]
    public async Task Run_UR_ArcMotion_RefusedWithItsLine_NothingSent()
    {
        using var cli = new CliRunner();
        string program = "SpeedTo(100);\nMoveTo(300, 0, 400);\n" + string.Concat(Enumerable.Repeat("Move(0, 0, 1);\n", 11)) + "ArcMotionTo(375, 0, 360, 300, 100, 300);\nMove(0, 0, 1);\n";

        CliResult result = await cli.RunProgramAsync("run", program, "--brand", "ur", "--sim", "--speed-factor", "1000");

        Assert.Equal(1, result.Exit);
        Assert.Equal("p.machina:14:1: error: ArcMotionTo(375,0,360,300,100,300); cannot be applied: \"Arc motion through [375, 0, 360] to [300, 100, 300]\" " +
            "cannot be streamed to a UR robot: Machina's UR driver has no instruction for it. Nothing was sent; the robot did not move.", result.Stderr.TrimEnd());
        Assert.DoesNotContain("Streaming", result.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("%", result.Stdout, StringComparison.Ordinal); // no action executed
    }

    [Fact]
    public async Task Run_Sim_TargetOutOfReach_RefusedWithItsLine_NothingSent()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("run", "MoveTo(300, 0, 400);\nWait(5);\n  MoveTo(5000, 0, 400);\nMoveTo(300, 0, 400);\n", "--brand", "abb", "--sim", "--speed-factor", "1000");

        Assert.Equal(1, result.Exit);
        Assert.StartsWith("p.machina:3:3: error: MoveTo(5000,0,400); cannot be reached by the IRB 120: ", result.Stderr, StringComparison.Ordinal);
        Assert.Contains("Nothing was sent; the robot did not move.", result.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("Streaming", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_SeveralProblems_AllListed()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("run", "MoveTo(300, 0, 400);\nMoveTo(5000, 0, 400);\nMoveTo(300, 0, 400);\nMoveTo(0, 0, -3000);\n", "--brand", "abb", "--sim", "--speed-factor", "1000");

        Assert.Equal(1, result.Exit);
        string[] lines = result.Stderr.Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.StartsWith("p.machina:2:1: error: MoveTo(5000,0,400); cannot be reached", lines[0], StringComparison.Ordinal);
        Assert.StartsWith("p.machina:4:1: error: MoveTo(0,0,-3000); cannot be reached", lines[1], StringComparison.Ordinal);
        Assert.Equal("2 problems: nothing was sent; the robot did not move.", lines[2].TrimEnd('\r'));
    }

    [Fact]
    public void VirtualModel_IsTheVirtualControllersArm()
    {
        Assert.Equal("IRB 120", RunCheck.VirtualModel(RobotType.ABB)!.Name);
        Assert.Equal("UR5e", RunCheck.VirtualModel(RobotType.UR)!.Name);
        Assert.Equal("KR 6 R900 sixx", RunCheck.VirtualModel(RobotType.KUKA)!.Name);
        Assert.Null(RunCheck.VirtualModel(RobotType.ZMORPH));
    }

    [Fact]
    public void FailedError_NamesTheLineTheActionAndTheControllersReason()
    {
        var action = new ActionTranslation(new Vector(5000, 0, 400), false);
        var failure = new ActionFailedException(action, "Position outside reach", "50050");

        CliException located = RunCommand.FailedError("p.machina", new InstructionStatement(action, 14, 3), failure);
        CliException unlocated = RunCommand.FailedError("p.machina", null, new ActionFailedException(action, "Stopped", null));

        Assert.Equal("p.machina:14:3: error: the controller could not run MoveTo(5000,0,400); and stopped: Position outside reach (error 50050).", located.Message);
        Assert.True(located.IsLocated);
        Assert.Equal("p.machina: the controller could not run MoveTo(5000,0,400); and stopped: Stopped.", unlocated.Message);
    }
}

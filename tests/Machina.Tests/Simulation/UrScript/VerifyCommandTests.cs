// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.UrScript;

public class VerifyCommandTests
{
    [Fact]
    public async Task Verify_Program_RunsItsCompiledScriptOnTheTwin_AndAgreesStepByStep()
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", "SpeedTo(100);\nMoveTo(400, 0, 300);\nMove(50, 0, 0);\nWriteDigital(2, true);\nMove(0, 50, 0);\n");

        CliResult result = await cli.RunAsync("verify", "square.machina", "--brand", "ur");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.True(result.Stdout.Contains("   2 line 3     ok   Move(50,0,0);\n", StringComparison.Ordinal), result.Stdout);
        Assert.True(result.Stdout.Contains("   3 line 4     ok   WriteDigital(2,True);\n", StringComparison.Ordinal), result.Stdout);
        Assert.EndsWith("OK: 4 steps agree; the program runs in 1.066 s\n", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Verify_EditedScript_ReportsTheStepThatDiffers()
    {
        using var cli = new CliRunner();
        cli.Write("line.machina", "MoveTo(400, 0, 300);\nMove(50, 0, 0);\n");
        cli.Write("line.script", "def line():\n  movel(p[0.4, 0, 0.3, 0, 3.141593, 0])\n  movel(p[0.45, 0, 0.302, 0, 3.141593, 0])\nend\n");

        CliResult result = await cli.RunAsync("verify", "line.machina", "--brand", "ur", "--script", "line.script");

        Assert.Equal(1, result.Exit);
        Assert.True(result.Stdout.Contains("   2 line 2     DIFF Move(50,0,0);\n", StringComparison.Ordinal), result.Stdout);
        Assert.True(result.Stdout.Contains("       the TCP is 2 mm away\n", StringComparison.Ordinal), result.Stdout);
        Assert.EndsWith("FAILED: 1 of 2 steps differ\n", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Verify_StopsPartWay_NumbersTheProgramFilesLines_AndSaysNotReached()
    {
        using var cli = new CliRunner();
        cli.Write("far.machina", "// a target out of reach\nMoveTo(400, 0, 300);\n\nMoveTo(4000, 0, 300);\nMove(0, 50, 0);\n");

        CliResult result = await cli.RunAsync("verify", "far.machina", "--brand", "ur");

        Assert.Equal(1, result.Exit);
        Assert.True(result.Stdout.Contains("   1 line 2     ok   MoveTo(400,0,300);\n", StringComparison.Ordinal), result.Stdout);
        Assert.True(result.Stdout.Contains("   2 line 4     not reached MoveTo(4000,0,300);\n", StringComparison.Ordinal), result.Stdout);
        Assert.True(result.Stdout.Contains("   3 line 5     not reached Move(0,50,0);\n", StringComparison.Ordinal), result.Stdout);
        Assert.DoesNotContain("line 0", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task OverlappingBlends_CompilerTwinAndVerify_AgreeTheControllerWarnsAndRunsOn()
    {
        using var cli = new CliRunner();
        cli.Write("short.machina", "SpeedTo(100);\nPrecisionTo(5);\nMoveTo(400, 0, 300);\nMove(4, 0, 0);\nMove(0, 50, 0);\n");

        CliResult compiled = await cli.RunAsync("compile", "short.machina", "--brand", "ur", "--out", "build");
        CliResult verified = await cli.RunAsync("verify", "short.machina", "--brand", "ur");

        Assert.Equal(0, compiled.Exit);
        Assert.Contains("short.machina:4:1: warning: Move(4,0,0); the blend radius of 5 mm is more than half of this motion (4 mm long); blends cannot overlap: "
            + "a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(2) or less around short motions.",
            compiled.Stderr, StringComparison.Ordinal);
        // The twin runs on, as the manual says a controller does, and logs the warning, which verify prints.
        Assert.True(verified.Exit == 0, verified.Stdout);
        Assert.Matches(@"(?m)^controller: Warning: line \d+: move[lp]: the blend radius 5 mm is more than half of this motion \(4 mm long\): "
            + @"blends cannot overlap; it blends with 2 mm$", verified.Stdout);
        Assert.Contains("OK: 3 steps agree", verified.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Verify_ScriptAlone_ListsItsStepsOrTheControllersError()
    {
        using var cli = new CliRunner();
        cli.Write("ok.script", "def ok():\n  movej([0, -1.570796, 1.570796, -1.570796, -1.570796, 0], a=1, v=1)\n  set_standard_digital_out(3, True)\nend\n");
        cli.Write("bad.script", "def bad():\n  movej([0, 0, 0, 0, 0, 0])\n  movl(p[0.4, 0, 0.3, 0, 3.14, 0])\nend\n");

        CliResult ok = await cli.RunAsync("verify", "ok.script", "--brand", "ur");
        CliResult bad = await cli.RunAsync("verify", "bad.script", "--brand", "ur");

        Assert.Equal(0, ok.Exit);
        Assert.True(ok.Stdout.Contains("  line 3         0.001 s  standard_digital_out[3] = True: TCP [-491.9, -133.3, 487.9], joints [0, -90, 90, -90, -90, 0]\n", StringComparison.Ordinal), ok.Stdout);
        Assert.EndsWith("OK: the program ran to its end in 0.001 s\n", ok.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, bad.Exit);
        Assert.EndsWith("FAILED: Compile error: line 3: unknown function 'movl'\n", bad.Stdout, StringComparison.Ordinal);
    }
}
#endif

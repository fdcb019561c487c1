// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.Rapid;

public class RapidVerifyCommandTests
{
    [Fact]
    public async Task Verify_Program_RunsItsCompiledRapidOnTheTwin_AndAgreesStepByStep()
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", "SpeedTo(100);\nMoveTo(300, 0, 300);\nMove(50, 0, 0);\nMove(0, 50, 0);\n");

        CliResult result = await cli.RunAsync("verify", "square.machina", "--brand", "abb");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.StartsWith("Running the compiled program on a RAPID twin of an ABB IRB 120 and comparing it with square.machina.\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains(" ok   Move(50,0,0);\n", result.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"OK: 3 steps agree; the program runs in [0-9.]+ s\n$", result.Stdout);
    }

    /// <summary>
    /// A program that waits for and reads named inputs (issue 46): verify declares them in the twin's IO configuration as it
    /// declares the outputs, so the compiled module loads and runs (before: "Load error: … 'DI_Part' is unknown").
    /// </summary>
    [Fact]
    public async Task Verify_ProgramWithNamedInputs_DeclaresThem_AndRuns()
    {
        using var cli = new CliRunner();
        cli.Write("inputs.machina", "SpeedTo(100);\nMoveTo(300, 0, 300);\nWaitForDigital(\"DI_Part\", false, 500);\nReadDigital(\"DI_Part\");\nReadAnalog(\"AI_Flow\");\nWriteDigital(\"DO_Done\", true);\nMove(0, 50, 0);\n");

        CliResult result = await cli.RunAsync("verify", "inputs.machina", "--brand", "abb");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.DoesNotContain("unknown", result.Stdout, StringComparison.Ordinal);
        Assert.Contains(" ok   WriteDigital(\"DO_Done\",True);\n", result.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"OK: 3 steps agree; the program runs in [0-9.]+ s\n$", result.Stdout);
    }

    [Fact]
    public async Task Verify_ModuleAlone_ListsItsSteps_OrRefusesAnUnknownInstructionWithItsLine()
    {
        using var cli = new CliRunner();
        cli.Write("ok.mod", "MODULE ok\nPROC main()\n  MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;\nENDPROC\nENDMODULE\n");
        cli.Write("bad.mod", "MODULE bad\nPROC main()\n  MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;\n  MoveLL p10, v100, z5, tool0;\nENDPROC\nENDMODULE\n");

        CliResult ok = await cli.RunAsync("verify", "ok.mod", "--brand", "abb");
        CliResult bad = await cli.RunAsync("verify", "bad.mod", "--brand", "abb");

        Assert.True(ok.Exit == 0, ok.Stdout + ok.Stderr);
        Assert.Contains("  line 3         0.000 s  MoveAbsJ: TCP [302, 0, 558], joints [0, 0, 0, 0, 90, 0]\n", ok.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("OK: the program ran to its end in 0 s\n", ok.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, bad.Exit);
        Assert.Equal("FAILED: bad.mod: Load error: line 4: Reference error: 'MoveLL' is not a procedure (unknown instruction)\n", bad.Stdout);
    }
}
#endif

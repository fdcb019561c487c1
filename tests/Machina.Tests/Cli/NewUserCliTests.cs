// The command-line tool is built for .NET 10 only (see Machina.Tests.csproj).
#if NET10_0_OR_GREATER
namespace Machina.Tests.Cli;

/// <summary>What a new user read from the command line (issue 46): wording per brand, counts that agree with their noun.</summary>
public class NewUserCliTests
{
    [Fact]
    public async Task Drivers_UrWithoutHost_AsksForThisComputersAddress()
    {
        using var cli = new CliRunner();

        CliResult ur = await cli.RunAsync("drivers", "ur", "--port", "7000", "--out", "driver");
        CliResult abb = await cli.RunAsync("drivers", "abb", "--port", "7000", "--out", "driver");

        Assert.Equal(2, ur.Exit);
        Assert.Contains("machina drivers needs --host (this computer's address, which the UR driver script connects back to, e.g. 192.168.56.1).",
            ur.Stderr, StringComparison.Ordinal);
        Assert.DoesNotContain("the controller's address", ur.Stderr, StringComparison.Ordinal);
        Assert.Contains("machina drivers needs --host (the controller's address, e.g. 192.168.125.1).", abb.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Run_Sim_OneAction_SaysOneAction()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunProgramAsync("run", "MoveTo(300, 0, 400);\n", "--brand", "abb", "--sim", "--speed-factor", "1000");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("p.machina checked: 1 action,", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("Done: 1 action executed.", result.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("1 actions", result.Stdout + result.Stderr, StringComparison.Ordinal);
    }
}
#endif

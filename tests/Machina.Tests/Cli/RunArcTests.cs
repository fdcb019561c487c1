using Machina.Tests.Conventions;

namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina run</c> takes what <c>machina compile</c> takes (issue 46): the README's square, with its arc, streams to the
/// virtual UR (movec) and the virtual KUKA (CIRC) and ends where the program says.
/// </summary>
public class RunArcTests
{
    [Theory]
    [InlineData("ur")]
    [InlineData("kuka")]
    public async Task Run_SquareSample_WithItsArc_Sim_ExitsZero(string brand)
    {
        using var cli = new CliRunner();
        string square = Path.Combine(ConventionTests.RepositoryRoot(), "samples", "programs", "square.machina");

        CliResult result = await cli.RunAsync("run", square, "--brand", brand, "--sim", "--speed-factor", "1000");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("square.machina checked: 15 actions", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("Done: 15 actions executed.", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("axes [0, 0, 0, 0, 90, 0]", result.Stdout, StringComparison.Ordinal);
    }
}

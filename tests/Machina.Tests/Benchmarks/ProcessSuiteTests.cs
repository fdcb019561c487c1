using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>
/// Smoke test of the whole-process benchmarks: with --quick every scenario starts its child processes, which do the real work
/// (compile a file, stream to a controller) and report; no timing is asserted, only that each ran and measured something sane.
/// </summary>
public class ProcessSuiteTests
{
    [Fact]
    public void Run_Quick_EveryScenarioMeasuresItsTarget()
    {
        (int exitCode, List<ProcessResult> results) = ProcessSuite.Run(Options.Parse(["--process", "--quick"]), print: false);

        Assert.All(results, r => Assert.Null(r.Error));
        Assert.Equal(0, exitCode);
        Assert.Equal(ProcessSuite.All().Select(s => s.Name), results.Select(r => r.Scenario));
        Assert.All(results, r =>
        {
            Assert.Single(r.ProcessSeconds);
            Assert.InRange(r.StartupSeconds, 1e-4, r.ProcessSeconds[0]);
            Assert.InRange(r.ColdWorkSeconds, 1e-4, r.ProcessSeconds[0]);
            Assert.InRange(r.PeakResidentBytes, 10L << 20, 2L << 30);
            Assert.True(r.Ratio is > 0 and < double.PositiveInfinity, $"{r.Scenario}: ratio {r.Ratio}");
            Assert.NotEqual("-", r.TargetText);
        });
        Assert.All(results.Where(r => r.Scenario.StartsWith("cold-compile", StringComparison.Ordinal) && !r.Scenario.Contains("10m", StringComparison.Ordinal)),
            r => Assert.InRange(r.WarmWorkSeconds!.Value, 1e-5, 60));
        Assert.Contains("over 999", results.Single(r => r.Scenario == "cold-first-ack").Note, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData(new[] { 10_000, 100_000, 1_000_000 }, new[] { 1.0, 10.0, 100.0 }, "1.00")]
    [InlineData(new[] { 10_000, 1_000_000 }, new[] { 50.0, 50.0 }, "0.00")]
    [InlineData(new[] { 10_000 }, new[] { 1.0 }, "-")]
    public void Exponent_PowerLaw_IsItsPower(int[] sizes, double[] values, string expected)
    {
        Assert.Equal(expected, ProcessSuite.Exponent(sizes.Zip(values)));
    }
}

using Machina.Benchmarks.Fuzz;

namespace Machina.Tests.Benchmarks;

/// <summary>
/// A small seeded subset of the interpreters' fuzz run (the big one is <c>Machina.Benchmarks --fuzz</c>, see docs/reliability.md):
/// mutated golden files and drivers and random programs, each ending as the program's outcome, never with another exception or a
/// hang. Cases run on a 1 MB stack, as on the smallest host thread.
/// </summary>
public class InterpreterFuzzTests
{
    private const int Cases = 1_500;

    [Theory]
    [InlineData("ur")]
    [InlineData("rapid")]
    [InlineData("krl")]
    public void SeededCases_EndAsTheProgramsOutcome_NeverACrashOrAHang(string name)
    {
        FuzzLanguage language = FuzzLanguage.All(FuzzLanguage.RepositoryRoot()).Single(l => l.Name == name);

        FuzzReport report = FuzzRun.Run(language, Cases, seed: 40);

        Assert.Null(report.Hang);
        Assert.Empty(report.Crashes);
        Assert.Equal(Cases, report.Cases);
        Assert.True(report.Outcomes.GetValueOrDefault("refused") > 0, report.ToString());
        Assert.True(report.Outcomes.GetValueOrDefault("finished") > 0, report.ToString());
    }
}

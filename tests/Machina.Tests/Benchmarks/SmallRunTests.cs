using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>
/// A scenario's small run (<see cref="Scenario.SmallRun"/>): the harness calls it, after <c>Prepare</c> and before the warm-ups, as
/// often as the JIT's two promotions of the code a run calls once need (the plain rows' connect and disconnect, the wait for
/// completion), so that those promotions no longer fall inside the measured runs.
/// </summary>
public class SmallRunTests
{
    [Fact]
    public void Run_CallsTheSmallRun_RoundsTimes16_AfterThePrepare_BeforeTheWarmUps()
    {
        var order = new List<string>();
        var runner = new Runner(2, 1, _ => { }, settle: true, listeners: () => new RunListeners(null, null));

        Measurement m = runner.Run(new Probe(order), 10);

        Assert.Equal("info", m.Status);
        Assert.Equal(80, Runner.OncePerRunRounds * 16);
        Assert.Equal(["prepare", .. Enumerable.Repeat("small", 80), "work"], order.Take(82));
        Assert.Equal(80, order.Count(o => o == "small"));
        Assert.Equal(m.Warmups + 1 + m.RepeatedRuns, order.Count(o => o == "work")); // a run in which the JIT compiled is run again
    }

    [Theory]
    [InlineData(0, true)]    // --warmup 0
    [InlineData(1, false)]   // --quick: no settling
    public void Run_WithoutWarmUpsOrSettling_MakesNoSmallRun(int warmups, bool settle)
    {
        var order = new List<string>();
        var runner = new Runner(warmups, 1, _ => { }, settle: settle, listeners: () => new RunListeners(null, null));

        runner.Run(new Probe(order), 10);

        Assert.Equal(["prepare", "work"], order.Take(2));
        Assert.DoesNotContain("small", order);
    }

    [Fact]
    public void PlainAndSteadyRows_HaveASmallRun_OtherScenariosNone()
    {
        IReadOnlyList<Scenario> all = Catalog.All(new Workloads());

        Assert.Equal(
            ["plain-abb", "plain-ur", "plain-kuka", "steady-abb", "steady-ur", "steady-kuka"],
            all.Where(s => s.SmallRun() is not null).Select(s => s.Name));
        Assert.Equal(8, PlainProgramScenario.SmallRunSize);
    }

    /// <summary>Notes its Prepare, each small run and each call of its work.</summary>
    private sealed class Probe(List<string> order) : Scenario
    {
        public override string Name => "probe";

        public override string Title => "probe";

        public override int TargetSize => 10;

        public override Target? Target => null;

        public override Func<object?> Prepare(int size)
        {
            order.Add("prepare");
            return () =>
            {
                order.Add("work");
                return null;
            };
        }

        public override Action? SmallRun() => () => order.Add("small");
    }
}

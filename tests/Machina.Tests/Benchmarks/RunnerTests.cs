using System.Reflection.Emit;
using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>
/// The harness's runner: its event listeners are made before the scenario's <c>Prepare</c> starts threads (made beside a twin's
/// threads, a listener deadlocked with one of them: the `plain-abb` hangs), and a measured run in which the JIT compiled a method
/// is run again, so that "the JIT settled" is true of the runs a row reports.
/// </summary>
public class RunnerTests
{
    [Fact]
    public void Run_MakesItsListenersBeforeThePrepare()
    {
        var order = new List<string>();
        var scenario = new Probe(order, compiles: false);
        var runner = new Runner(1, 1, _ => { }, settle: false, listeners: () =>
        {
            order.Add("listeners");
            return new RunListeners(null, null);
        });

        Measurement m = runner.Run(scenario, 10);

        Assert.Equal("info", m.Status);
        Assert.Equal(["listeners", "prepare"], order.Take(2));
    }

    [Fact]
    public void Run_MeasuredRunsThatCompiled_AreRunAgain_AtMostAsManyAsAsked_AndTheRowIsBusy()
    {
        var order = new List<string>();
        // Every call compiles a method of its own: every measured run is one the JIT was busy in.
        var scenario = new Probe(order, compiles: true);
        var runner = new Runner(1, 2, _ => { }, settle: false, listeners: () => new RunListeners(null, null));

        Measurement m = runner.Run(scenario, 10);

        Assert.Equal(2, m.RepeatedRuns);
        Assert.Equal(m.Warmups + 4, scenario.Calls); // the two runs asked for and each again, no more
        Assert.False(m.JitSettled);
        Assert.True(m.JitMethods >= 1);
    }

    [Fact]
    public void Kept_TakesTheRunsThatCompiledNothing_ThenTheLastThatDid()
    {
        static Runner.Sample S(long methods, double seconds) => new(seconds, seconds, 0, 0, 0, "", 0, 0) { JitMethods = methods };

        List<Runner.Sample> clean = Runner.Kept([S(5, 1), S(0, 2), S(0, 3), S(3, 4), S(0, 5)], 3);
        List<Runner.Sample> short_ = Runner.Kept([S(5, 1), S(0, 2), S(7, 3), S(2, 4)], 3);

        Assert.Equal([2.0, 3.0, 5.0], clean.Select(s => s.Seconds));
        Assert.Equal([2.0, 3.0, 4.0], short_.Select(s => s.Seconds));
    }

    /// <summary>A scenario that notes its Prepare and counts its work's calls; with <c>compiles</c> each call makes the JIT compile a new method.</summary>
    private sealed class Probe(List<string> order, bool compiles) : Scenario
    {
        public int Calls { get; private set; }

        public override string Name => "probe";

        public override string Title => "probe";

        public override int TargetSize => 10;

        public override Target? Target => null;

        public override Func<object?> Prepare(int size)
        {
            order.Add("prepare");
            return () =>
            {
                Calls++;
                return compiles ? Compiled() : null;
            };
        }

        /// <summary>A method made now, so the JIT compiles it at its first call.</summary>
        private static object? Compiled()
        {
            var method = new DynamicMethod("probe", typeof(int), Type.EmptyTypes);
            ILGenerator il = method.GetILGenerator();
            il.Emit(OpCodes.Ldc_I4, 45);
            il.Emit(OpCodes.Ret);
            return ((Func<int>)method.CreateDelegate(typeof(Func<int>)))();
        }
    }
}

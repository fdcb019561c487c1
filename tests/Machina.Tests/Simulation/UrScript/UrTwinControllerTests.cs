using System.Diagnostics;
using System.Text;
using Machina.Simulation.UrScript;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation.UrScript;

public class UrTwinControllerTests(ITestOutputHelper output)
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(20);

    [Fact]
    public void Receive_DefInPiecesWithoutFinalLineBreak_StartsOnceAndSkipsItsCallLine()
    {
        using var twin = new UrTwinController();
        twin.Receive("def hello():\n  textmsg(\"hel");
        twin.Receive("lo\")\n");
        Assert.Equal(0, twin.ProgramsStarted);
        twin.Receive("end");
        Assert.True(twin.WaitForEnd(Bound));
        twin.Receive("\nhello()\n");
        Assert.True(twin.WaitForEnd(Bound));
        Assert.Equal(1, twin.ProgramsStarted);
        Assert.Equal(UrProgramState.Finished, twin.State);
        Assert.Equal(["hello"], twin.Pendant.Lines);
    }

    [Fact]
    public void Receive_NewProgram_StopsTheRunningOne()
    {
        using var twin = new UrTwinController();
        twin.Receive("def spin():\n  textmsg(\"spinning\")\n  while True:\n    sync()\n  end\nend\n");
        SpinWait.SpinUntil(() => twin.Pendant.Lines.Count > 0, Bound);
        Assert.Equal(UrProgramState.Running, twin.State);
        twin.Receive("def second():\n  textmsg(\"second\")\nend\n");
        Assert.True(twin.WaitForEnd(Bound));
        Assert.Equal(2, twin.ProgramsStarted);
        Assert.Equal(UrProgramState.Finished, twin.State);
        Assert.Equal(["spinning", "second"], twin.Pendant.Lines);
    }

    [Fact]
    public void Start_TwoConnectionsAtOnce_EachNewProgramStopsTheLastWithoutFailing()
    {
        // Two clients' programs arriving together: each Start stops (and joins) the program the other just started. The thread
        // was once published before it was started, and joining it then threw ThreadStateException, which dropped the
        // connection's program silently (NetworkIntakeTests failed now and then under load).
        using var twin = new UrTwinController();
        // 200 starts each still interleave the two threads hundreds of times; 400 each took over the
        // 20 s bound at a load average of 75 (every start joins a thread that must first be scheduled), so the count is what bounds it.
        const int perThread = 200;
        using var ready = new Barrier(2);
        var failures = new System.Collections.Concurrent.ConcurrentQueue<Exception>();
        void StartMany(string name)
        {
            ready.SignalAndWait(Bound);
            for (int i = 0; i < perThread; i++)
            {
                try
                {
                    twin.Start($"def {name}():\n  textmsg(\"{name}\")\nend\n");
                }
                catch (Exception ex)
                {
                    failures.Enqueue(ex);
                }
            }
        }
        var first = new Thread(() => StartMany("first"));
        var second = new Thread(() => StartMany("second"));
        first.Start();
        second.Start();
        Assert.True(first.Join(Bound) && second.Join(Bound), "the two starting threads did not finish");
        Assert.True(twin.WaitForEnd(Bound));
        Assert.Empty(failures.Select(f => f.GetType().Name + ": " + f.Message).Distinct());
        Assert.Equal(2 * perThread, twin.ProgramsStarted);
    }

    [Fact]
    public void Receive_ProgramWithCompileError_IsRefusedAndTheRunningOneGoesOn()
    {
        using var twin = new UrTwinController();
        twin.Receive("def spin():\n  while True:\n    sync()\n  end\nend\n");
        twin.Receive("def bad():\n  movej([0, 0, 0, 0, 0])\n  nosuch()\nend\n");
        Assert.Equal("Compile error: line 3: unknown function 'nosuch'", twin.Error);
        Assert.Equal(1, twin.ProgramsStarted);
        Assert.False(twin.WaitForEnd(TimeSpan.FromMilliseconds(50)));
        Assert.Equal(UrProgramState.Running, twin.State); // the refused program failed, not the running one
        twin.StopProgram();
        Assert.Equal(UrProgramState.Stopped, twin.State);
    }

    [Theory]
    [InlineData("movej([1, -1.570796, 1.570796, -1.570796, -1.570796, 0], a=1, v=1)", 2.0)] // 1 rad: 1/1 + 1/1
    [InlineData("movej([0.25, -1.570796, 1.570796, -1.570796, -1.570796, 0], a=1, v=1)", 1.0)] // triangle: 2 sqrt(0.25/1)
    [InlineData("movej([0.25, -1.570796, 1.570796, -1.570796, -1.570796, 0], t=3)", 3.0)]
    [InlineData("movel(pose_trans(get_actual_tcp_pose(), p[0, 0, 0.1, 0, 0, 0]), a=1.2, v=0.25)", 0.1 / 0.25 + 0.25 / 1.2)]
    [InlineData("sleep(0.75)", 0.75)]
    public void Motion_TakesTheTrapezoidTime(string move, double seconds)
    {
        using var twin = new UrTwinController();
        Assert.Equal(UrProgramState.Finished, twin.Run($"def m():\n  {move}\nend"));
        Assert.Equal(seconds, twin.Clock.Seconds, 4);
    }

    [Fact]
    public void Movel_ReachesThePoseWithTheActiveTcp()
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("""
            def m():
              set_tcp(p[0, 0, 0.1, 0, 0, 0])
              movej(p[0.4, -0.1, 0.5, 0, 3.141593, 0])
              movel(p[0.4, -0.1, 0.3, 0, 3.141593, 0], v=0.5)
              x = get_actual_tcp_pose()
              textmsg(x)
              q = get_inverse_kin(x)
              textmsg(norm(pose_dist(get_forward_kin(q), x)) < 0.000001, "")
            end
            """);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        Pose tcp = twin.Arm.Tcp;
        Assert.Equal(400, tcp.Position.X, 6);
        Assert.Equal(-100, tcp.Position.Y, 6);
        Assert.Equal(300, tcp.Position.Z, 6);
        Assert.Equal(400, twin.Arm.Flange.Position.X, 3);
        Assert.Equal(400, twin.Arm.Flange.Position.Z, 3);
        // A rotation of (almost) 180 deg reads back as the opposite rotation vector: the same orientation.
        Assert.Equal(["p[0.4, -0.1, 0.3, 0, -3.141592, 0]", "True"], twin.Pendant.Lines);
    }

    [Fact]
    public void Load_HundredThousandLines_CompilesAndStartsWithinASecond()
    {
        var text = new StringBuilder("def big():\n  x = 0\n");
        for (int i = 0; i < 100_000; i++)
        {
            text.Append("  x = x + 1 # line ").Append(i).Append('\n');
        }
        text.Append("  textmsg(\"x=\", x)\nend\n");
        string program = text.ToString();
        // Wall time on a shared, loaded machine says little: the processor time of this process is measured too (the test
        // class runs alone in its collection, so it is mostly this test's).
        using var twin = new UrTwinController();
        UrBoundProgram bound = UrTwinController.Compile(program);
        var process = Process.GetCurrentProcess();
        TimeSpan cpuBefore = process.TotalProcessorTime;
        var clock = Stopwatch.StartNew();
        Assert.Equal(UrProgramState.Finished, twin.Run(program));
        TimeSpan wall = clock.Elapsed;
        process.Refresh();
        TimeSpan cpu = process.TotalProcessorTime - cpuBefore;
        output.WriteLine($"100,002 lines, compile and run to the end: {wall.TotalMilliseconds:0} ms wall, {cpu.TotalMilliseconds:0} ms processor");
        Assert.Equal(["x=100000"], twin.Pendant.Lines);
        Assert.NotNull(bound.Entry);
        Assert.True(cpu < TimeSpan.FromSeconds(3), $"compiling and running took {cpu} of processor time");
    }
}

using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// WAIT SEC in the submit interpreter holds that interpreter only (session 36, tp56): before, it went through the robot's wait,
/// so each one was a step of the arm's trace (<c>machina sim kuka --load</c> printed 6,031 such lines while KUKA's EKI server
/// ran), added its seconds to the robot program's time and ended the robot's advance run from the other thread.
/// </summary>
public class KrlSubmitWaitTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(30);

    [Fact]
    public async Task SubmitWaitSec_IsNoStepOfTheArmsTrace()
    {
        // The submit program waits twice once the robot program runs ($OUT[2]), then sets the global the robot program waits for
        // (gates, not sleeps; a running timer lets the WAIT FOR wait for the other interpreter): the robot's own WAIT SEC is the
        // trace's one wait.
        const string robot = "DEF cell( )\n  $TIMER_STOP[1] = FALSE\n  $OUT[2] = TRUE\n  WAIT FOR go\n  WAIT SEC 0.25\n  $OUT[1] = TRUE\nEND\n";
        const string submit = "DEF sps( )\n  IF $OUT[2] AND NOT go THEN\n    WAIT SEC 0.02\n    WAIT SEC 0.03\n    turns = turns + 1\n    go = TRUE\n  ENDIF\nEND\n";
        const string data = "DEFDAT sps PUBLIC\n  DECL GLOBAL BOOL go = FALSE\n  DECL GLOBAL INT turns = 0\nENDDAT\n";
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", robot), ("sps.sub", submit), ("sps.dat", data));
        using var stop = new CancellationTokenSource(Bound);

        Task submitting = Task.Factory.StartNew(() => twin.RunSubmit("sps", TimeSpan.FromMilliseconds(4), stop.Token), TaskCreationOptions.LongRunning);
        Assert.True(SpinWait.SpinUntil(() => twin.SubmitProgramState == "P_ACTIVE", Bound), "the submit interpreter did not start");
        Task<KrlProgramState> running = Task.Factory.StartNew(() => twin.Run(cancellation: stop.Token), TaskCreationOptions.LongRunning);
        KrlProgramState state = await running.WaitAsync(Bound);
        await stop.CancelAsync();
        await submitting.WaitAsync(Bound);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(1, (int)twin.Modules["sps"].Data["turns"].Value);
        Assert.Equal(["WAIT SEC 0.25"], twin.Arm.Trace.Where(s => s.Text.StartsWith("WAIT", StringComparison.Ordinal)).Select(s => s.Text));
        Assert.DoesNotContain(twin.Pendant.Lines, l => l.Contains("Submit interpreter stopped", StringComparison.Ordinal));
    }
}

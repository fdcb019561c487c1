using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The line a KRL twin's trace gives a written output: the line of the interpreter that wrote it. The robot interpreter and the
/// submit interpreter (the KUKA monitor in <c>sps.sub</c>) run on their own threads; when both kept one line, an output the robot
/// program wrote was traced at whatever line the submit interpreter had just run, as the threads met (a streamed <c>$OUT</c>
/// at the monitor's line 38 instead of the driver's 220, once in a few dozen differential runs).
/// </summary>
public class KrlTraceLineTests
{
    private const string SubmitData = "DEFDAT sps PUBLIC\n  DECL GLOBAL BOOL go = FALSE\n  DECL GLOBAL BOOL release = FALSE\n  DECL GLOBAL INT turns = 0\nENDDAT\n";

    private static readonly TimeSpan Bound = TimeSpan.FromSeconds(30);

    [Fact]
    public async Task SubmitInterpreterRunning_TheRobotsLineAndItsOutputsLines_AreTheRobotPrograms_TheSubmitsOutputsTheSubmits()
    {
        // The robot program waits at line 5; the submit program then runs its lines 2 and 3 every cycle. The robot's line stays 5
        // (it was the submit's last line, 2 or 3, when both wrote one), and an output written beside the robot program on another
        // thread (as RSI's cycle sets one) is traced at line 5. Released, the submit program writes $OUT[3] at its line 4, once.
        const string robot = "DEF cell( )\n  $TIMER[1] = 0\n  $TIMER_STOP[1] = FALSE\n  $OUT[2] = TRUE\n  WAIT FOR go\n  $TIMER_STOP[1] = TRUE\n  $OUT[1] = TRUE\nEND\n";
        const string submit = "DEF sps( )\n  turns = turns + 1\n  IF release THEN\n    $OUT[3] = TRUE\n    release = FALSE\n    go = TRUE\n  ENDIF\nEND\n";
        using var twin = new KrlTwinController();
        twin.Load(("cell.src", robot), ("sps.sub", submit), ("sps.dat", SubmitData));
        using var stop = new CancellationTokenSource(Bound);
        Task<KrlProgramState> running = Task.Factory.StartNew(() => twin.Run(cancellation: stop.Token), TaskCreationOptions.LongRunning);
        Assert.True(SpinWait.SpinUntil(() => twin.Line == 5, Bound), "the robot program did not reach its WAIT FOR");
        Task submitting = Task.Factory.StartNew(() => twin.RunSubmit("sps", TimeSpan.FromMilliseconds(4), stop.Token), TaskCreationOptions.LongRunning);
        Assert.True(SpinWait.SpinUntil(() => (int)twin.Modules["sps"].Data["turns"].Value >= 2, Bound), "the submit program did not run twice");

        int robotLine = twin.Line;
        twin.Io.SetBit("$OUT", 9, true);
        twin.OutputWritten("$OUT", 9);
        twin.Modules["sps"].Data["release"].Value = true;
        KrlProgramState state = await running.WaitAsync(Bound); // the robot program ends
        stop.Cancel();
        await submitting.WaitAsync(Bound); // the submit interpreter stops

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(5, robotLine);
        Assert.Equal(
            ["4 $OUT[2] = TRUE", "5 $OUT[10] = TRUE", "4 $OUT[3] = TRUE", "7 $OUT[1] = TRUE"],
            twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Output).Select(e => $"{e.Line} {e.Text}"));
    }
}

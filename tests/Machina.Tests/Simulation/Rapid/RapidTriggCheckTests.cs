using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// TriggCheckIO, TriggSpeed, TriggC and \ProcID, in programs of our own written the way gluing and gripper cells use them: a check
/// of a signal where the TCP passes its point (its trap runs there when the check fails, not when it holds), an analog output that
/// follows the TCP speed from its point on, events along a circle, and an event handed to a process. The numbers are the twin's
/// trapezoid: 100 mm at 250 mm/s and 1.2 m/s² ramps over 26.042 mm in 0.208333 s and takes 0.608333 s.
/// </summary>
public class RapidTriggCheckTests
{
    private const double Whole = 0.1 / 0.25 + 0.25 / 1.2;

    private static RapidTwinController Run(string declarations, string body, string traps = "")
    {
        var twin = new RapidTwinController(new RapidTwinOptions
        {
            Acceleration = 1.2,
            Signals = [("DO_1", "signaldo"), ("DO_2", "signaldo"), ("AO_1", "signalao")],
        });
        twin.Load(("T.mod", $$"""
            MODULE T
              CONST speeddata s250 := [250, 500, 5000, 1000];
              VAR robtarget p0;
              VAR robtarget p;
              VAR robtarget via;
              VAR robtarget at;
              VAR intnum checkInt;
              {{declarations}}
              PROC main()
                p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
                p := p0;
                p.trans.x := p0.trans.x + 100;
            {{body}}
              ENDPROC
              TRAP Failed
                at := CRobT(\Tool:=tool0 \WObj:=wobj0);
                TPWrite "check failed at " + NumToStr(at.trans.x - p0.trans.x, 1);
              ENDTRAP
            {{traps}}
            ENDMODULE
            """));
        RapidProgramState state = twin.Run();
        Assert.True(state == RapidProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void TriggCheckIO_RunsItsTrapWhereTheCheckFails_AndNotWhereItHolds()
    {
        RapidTwinController twin = Run("VAR triggdata gripClosed;", """
                CONNECT checkInt WITH Failed;
                TriggCheckIO gripClosed, 10 \Start, DO_1, EQ, 1, checkInt;
                TriggL p, s250, gripClosed, fine, tool0;
                TPWrite "first move done";
                SetDO DO_1, 1;
                TriggL p0, s250, gripClosed, fine, tool0;
                TPWrite "second move done";
            """);

        // The first check finds DO_1 at 0: its trap runs 10 mm from the start; the second finds it at 1: no trap.
        Assert.Equal(["check failed at 10", "first move done", "second move done"], twin.Pendant.Lines);
        Assert.Equal(2 * Whole, twin.Clock.Seconds, 5);
    }

    [Fact]
    public void TriggCheckIO_StopMove_HoldsTheRobotOnItsPathUntilTheTrapsStartMove()
    {
        RapidTwinController twin = Run("VAR triggdata gripClosed;", """
                CONNECT checkInt WITH GoOn;
                TriggCheckIO gripClosed, 30, DO_2, NOTEQ, 0 \StopMove, checkInt;
                TriggL p, s250, gripClosed, fine, tool0;
                at := CRobT(\Tool:=tool0 \WObj:=wobj0);
                TPWrite "done at " + NumToStr(at.trans.x - p0.trans.x, 1);
            """, """
              TRAP GoOn
                TPWrite "held " \Bool:=IsStopMoveAct(\FromNonMoveTask);
                SetDO DO_2, 1;
                StartMove;
              ENDTRAP
            """);

        Assert.Equal(["held TRUE", "done at 100"], twin.Pendant.Lines);
        Assert.False(twin.Arm.IsHeld);
        Assert.Equal(1, twin.Io.GetBit("do", 1) ? 1 : 0);
    }

    [Fact]
    public void TriggSpeed_SetsTheAnalogOutputToTheScaleTimesTheTcpSpeed_FromItsPoint_AndFollowsTheLastRampDownToZero()
    {
        RapidTwinController twin = Run("VAR triggdata flow;", """
                TriggSpeed flow, 50, 0, AO_1, 0.02;
                TriggL p, s250, flow, fine, tool0;
            """);

        TwinTraceEntry[] outputs = [.. twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Output)];
        // 50 mm before the end the TCP runs at its programmed 250 mm/s (the last ramp is 26 mm): 0.02 * 250 = 5; then the output
        // follows the speed down the last ramp, set again at each eighth of it, to 0 where the TCP stops.
        Assert.Equal(["AO_1 = 5", "AO_1 = 4.375", "AO_1 = 3.75", "AO_1 = 3.125", "AO_1 = 2.5", "AO_1 = 1.875", "AO_1 = 1.25", "AO_1 = 0.625", "AO_1 = 0"],
            outputs.Select(e => e.Text));
        const double ramp = 0.25 * 0.25 / (2 * 1.2); // metres
        Assert.Equal(0.25 / 1.2 + (0.05 - ramp) / 0.25, outputs[0].Seconds, 5);
        Assert.Equal(Whole - 0.25 / 1.2 * 7 / 8, outputs[1].Seconds, 5);
        Assert.Equal(Whole, outputs[^1].Seconds, 5);
    }

    [Fact]
    public void TriggSpeed_FromTheStart_FollowsTheFirstRampUp_AndScaleLagSetsEachValueThatMuchEarlier()
    {
        RapidTwinController twin = Run("VAR triggdata flow;", """
                TriggSpeed flow, 0 \Start, 0.05, AO_1, 0.04;
                TriggL p, s250, flow, fine, tool0;
            """);

        TwinTraceEntry[] outputs = [.. twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Output)];
        // 0.04 * the speed 0.05 s later: at the start 0.04 * 1.2 m/s² * 0.05 s = 2.4; up the ramp (0.2083 s) to 10 at 0.1583 s.
        Assert.Equal("AO_1 = 2.4", outputs[0].Text);
        Assert.Equal(0, outputs[0].Seconds, 5);
        TwinTraceEntry full = outputs.First(e => e.Text == "AO_1 = 10");
        Assert.Equal(0.25 / 1.2 - 0.05, full.Seconds, 5);
        Assert.Equal("AO_1 = 0", outputs[^1].Text);
        Assert.Equal(Whole - 0.05, outputs[^1].Seconds, 5);
        Assert.All(outputs.Zip(outputs.Skip(1)), pair => Assert.True(pair.First.Seconds <= pair.Second.Seconds));
    }

    [Fact]
    public void TriggC_FiresItsEventWhereTheToolPassesItsDistanceAlongTheCircle()
    {
        Pose start = new RapidTwinController().Arm.Tcp;
        RapidTwinController twin = Run("VAR triggdata on;", """
                via := p0;
                via.trans.x := p0.trans.x + 50;
                via.trans.y := p0.trans.y + 50;
                TriggIO on, 78.5398 \Start \DOp:=DO_1, 1;
                TriggC via, p, s250, on, fine, tool0;
            """);

        // A half circle of radius 50 mm from p0 through via to p: a quarter of it (78.54 mm) ends at the top, 50 mm from both.
        TwinTraceEntry output = Assert.Single(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Output);
        Assert.Equal(50, output.Tcp.Position.X - start.Position.X, 2);
        Assert.Equal(50, output.Tcp.Position.Y - start.Position.Y, 2);
        Assert.Equal(100, twin.Arm.Tcp.Position.X - start.Position.X, 4);
        Assert.Equal(0, twin.Arm.Tcp.Position.Y - start.Position.Y, 4);
    }

    [Fact]
    public void ProcID_HandsTheEventToItsProcessWithTheSelector_InsteadOfAnOutput()
    {
        Pose start = new RapidTwinController().Arm.Tcp;
        RapidTwinController twin = Run("VAR triggdata process;", """
                TriggIO process, 20 \ProcID:=3, 7;
                TriggL p, s250, process, fine, tool0;
            """);

        Assert.DoesNotContain(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Output);
        TwinTraceEntry message = Assert.Single(twin.Arm.Trace, e => e.Kind == TwinTraceKind.Message);
        Assert.Equal("ProcID 3: selector 7", message.Text);
        Assert.Equal(80, message.Tcp.Position.X - start.Position.X, 3); // 20 mm before the end of 100 mm
    }
}

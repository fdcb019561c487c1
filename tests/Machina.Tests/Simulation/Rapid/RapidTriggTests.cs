using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Fixed-position events (TriggIO, TriggEquip, TriggInt with TriggL and TriggJ), in programs of our own written the way dispensing and
/// gripper cells use them: each output is set, and each trap runs, where the TCP passes its point of the path and when. The numbers
/// are the twin's trapezoid: 100 mm at 250 mm/s and 1.2 m/s² ramps over 26.042 mm in 0.208333 s and takes 0.608333 s.
/// </summary>
public class RapidTriggTests
{
    private const double Ramp = 0.25 / 1.2, Whole = 0.1 / 0.25 + 0.25 / 1.2;

    private static RapidTwinController Run(string declarations, string body, string traps = "")
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2, Signals = [("DO_1", "signaldo"), ("DO_2", "signaldo")] });
        twin.Load(("T.mod", $$"""
            MODULE T
              CONST speeddata s250 := [250, 500, 5000, 1000];
              VAR robtarget p0;
              VAR robtarget p;
              VAR robtarget at;
              {{declarations}}
              PROC main()
                p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
                p := p0;
                p.trans.x := p0.trans.x + 100;
            {{body}}
              ENDPROC
            {{traps}}
            ENDMODULE
            """));
        RapidProgramState state = twin.Run();
        Assert.True(state == RapidProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    private static TwinTraceEntry[] Outputs(RapidTwinController twin) => [.. twin.Arm.Trace.Where(e => e.Kind == TwinTraceKind.Output)];

    [Fact]
    public void TriggL_SetsEachOutputWhereTheToolPassesItsDistance_AndRunsTheTriggIntTrapItsTimeBeforeTheEnd()
    {
        Pose start = new RapidTwinController().Arm.Tcp;
        RapidTwinController twin = Run(
            """
            VAR triggdata gunOn;
              VAR triggdata gunOff;
              VAR triggdata near;
              VAR intnum nearInt;
            """,
            """
                CONNECT nearInt WITH NearEnd;
                TriggIO gunOn, 10 \Start \DOp:=DO_1, 1;
                TriggIO gunOff, 20 \DOp:=DO_1, 0;
                TriggInt near, 0.2 \Time, nearInt;
                TriggL p, s250, gunOn \T2:=gunOff \T3:=near, z10, tool0;
                TPWrite "after " \Num:=DOutput(DO_1);
            """,
            """
              TRAP NearEnd
                at := CRobT(\Tool:=tool0 \WObj:=wobj0);
                TPWrite "trap at " + NumToStr(at.trans.x - p0.trans.x, 2) + " DO_1 " + NumToStr(DOutput(DO_1), 0);
              ENDTRAP
            """);

        // 10 mm from the start is on the ramp: sqrt(2 * 0.010 / 1.2) s. 20 mm before the end is on the last ramp: the whole move
        // less sqrt(2 * 0.020 / 1.2) s. 0.2 s before the end the tool is 1.2 * 0.2² / 2 m = 24 mm before it, and DO_1 is still on.
        TwinTraceEntry[] outputs = Outputs(twin);
        Assert.Equal(["DO_1 = 1", "DO_1 = 0"], outputs.Select(e => e.Text));
        Assert.Equal(Math.Sqrt(0.02 / 1.2), outputs[0].Seconds, 5);
        Assert.Equal(Whole - Math.Sqrt(0.04 / 1.2), outputs[1].Seconds, 5);
        Assert.Equal(10, outputs[0].Tcp.Position.X - start.Position.X, 3);
        Assert.Equal(80, outputs[1].Tcp.Position.X - start.Position.X, 3);
        Assert.Equal(0, outputs[1].Tcp.Position.Y - start.Position.Y, 3);
        Assert.Equal(["trap at 76 DO_1 1", "after 0"], twin.Pendant.Lines);
        Assert.Equal(Whole, twin.Clock.Seconds, 5);
        Assert.Equal(100, twin.Arm.Tcp.Position.X - start.Position.X, 6);
    }

    [Fact]
    public void TriggEquip_SetsItsOutputEquipLagEarlier_AndInhibitedSetsZero_OnTriggLAndTriggJ()
    {
        Pose start = new RapidTwinController().Arm.Tcp;
        RapidTwinController twin = Run(
            """
            VAR triggdata glue;
              PERS bool inhibit := FALSE;
            """,
            """
                TriggEquip glue, 50 \Start, 0.1 \DOp:=DO_2, 1 \Inhib:=inhibit;
                TriggL p, s250, glue, fine, tool0;
                inhibit := TRUE;
                TriggJ p0, s250, glue, fine, tool0;
            """);

        // 50 mm from the start is on the cruise: 0.208333 + (0.050 - 0.026042) / 0.25 s; 0.1 s earlier the tool is still on the
        // ramp, at 1.2 * 0.204167² / 2 m. Inhibited, the same event sets 0 on the way back, 0.204167 s into the second move.
        TwinTraceEntry[] outputs = Outputs(twin);
        Assert.Equal(["DO_2 = 1", "DO_2 = 0"], outputs.Select(e => e.Text));
        double at = Ramp + (0.05 - 0.25 * 0.25 / 2.4) / 0.25 - 0.1;
        Assert.Equal(at, outputs[0].Seconds, 5);
        Assert.Equal(1.2 * at * at / 2 * 1000, outputs[0].Tcp.Position.X - start.Position.X, 3);
        Assert.Equal(Whole + at, outputs[1].Seconds, 5);
        Assert.False(twin.Io.GetBit("do", 1));
        Assert.Equal(2 * Whole, twin.Clock.Seconds, 5);
    }
}

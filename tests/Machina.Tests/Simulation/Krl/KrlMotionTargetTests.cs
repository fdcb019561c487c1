using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// A Cartesian motion's start and target as the KRL twin reads them (issue 45, perf54m): a FRAME, POS or E6POS target, or an
/// aggregate of its X to C, is read as six numbers (the rest from where the arm stands), the answer of the driver's INVERSE is taken
/// again by its LIN with the poses it solved, and the arm reads its pending corner, joints and tool centre in one look. What the
/// program sees must be what the E6POS it converts to says: these tests pin the poses, times and messages.
/// </summary>
public class KrlMotionTargetTests
{
    private static KrlTwinController Run(string source, string data = "DEFDAT prog\nENDDAT\n", KrlProgramState expected = KrlProgramState.Finished)
    {
        var twin = new KrlTwinController();
        twin.Load([("prog.src", source), ("prog.dat", data)]);
        KrlProgramState state = twin.Run();
        Assert.True(state == expected, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void LinToAnAggregateOfX_MovesOnlyX_TheRestFromWhereTheArmStands_InTheTimeOfItsPath()
    {
        const string Source = """
            DEF prog( )
              $VEL.CP = 0.25
              $ACC.CP = 1.2
              PTP $AXIS_ACT
              LIN {X 400}
            END
            """;
        Pose start = new KrlTwinController().Arm.Tcp;

        KrlTwinController twin = Run(Source);

        TwinTraceEntry lin = twin.Arm.Trace.Last(e => e.Kind == TwinTraceKind.Motion);
        Assert.Equal(400, lin.Tcp.Position.X, 6);
        Assert.Equal(start.Position.Y, lin.Tcp.Position.Y, 6);
        Assert.Equal(start.Position.Z, lin.Tcp.Position.Z, 6);
        Assert.True(start.Rotation.AngleTo(lin.Tcp.Rotation) < 1e-6, "the tool turned");
        // The motion's time is its path's (from where the arm stood, in metres) at $VEL.CP with $ACC.CP.
        double metres = Math.Abs(400 - start.Position.X) / 1000;
        Assert.Equal(TwinMotion.TrapezoidSeconds(metres, 0.25, 1.2), twin.Clock.Seconds, 6); // the clock counts whole 100 ns
    }

    [Fact]
    public void LinToAPosVariable_AfterInverse_EndsAtInversesAxes_BitForBit_AndTracesTheirPose()
    {
        const string Data = """
            DEFDAT prog
              DECL E6AXIS solved
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL FRAME target
              DECL E6POS pose
              DECL INT err
              PTP $AXIS_ACT
              pose = $POS_ACT
              target.X = pose.X + 30
              target.Y = pose.Y - 20
              target.Z = pose.Z + 10
              target.A = pose.A + 5
              target.B = pose.B
              target.C = pose.C - 3
              pose.X = target.X
              pose.Y = target.Y
              pose.Z = target.Z
              pose.A = target.A
              pose.B = target.B
              pose.C = target.C
              err = 0
              solved = INVERSE(pose, $AXIS_ACT, err)
              LIN target C_DIS
            END
            """;

        KrlTwinController twin = Run(Source, Data);

        Joints solved = KrlTwinController.JointsOf((KrlStructValue)twin.Modules["prog"].Data["solved"].Value);
        TwinTraceEntry lin = twin.Arm.Trace.Last(e => e.Kind == TwinTraceKind.Motion);
        Assert.True(SameBits.Of(solved, lin.Joints), $"the LIN ended at {lin.Joints}, INVERSE answered {solved}");
        Assert.True(SameBits.Of(twin.Arm.Model.Kinematics.Forward(solved) * twin.Arm.ToolCenter, lin.Tcp));
        Assert.Equal("LIN C_DIS", lin.Text);
    }

    [Fact]
    public void UnreachableAggregate_StopsWithTheTargetsComponents_TheRestFromWhereTheArmStands()
    {
        const string Source = """
            DEF prog( )
              PTP {A1 0, A2 -90, A3 90, A4 0, A5 45, A6 0}
              LIN {X 100000, C 12.5}
            END
            """;

        KrlTwinController twin = Run(Source, expected: KrlProgramState.Failed);

        Pose now = twin.Arm.Tcp;
        string y = now.Position.Y.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture);
        Assert.StartsWith($"Target not reachable: LIN {{X 100000, Y {y}, ", twin.Error, StringComparison.Ordinal);
        Assert.Contains(", C 12.5}: it is outside the robot's workspace", twin.Error, StringComparison.Ordinal);
    }

    [Fact]
    public void PtpWithStatusAndTurn_TakesTheAxesOfThatStatusAndTurn_LinAfterIt_KeepsThem()
    {
        const string Data = """
            DEFDAT prog
              DECL INT s_after
              DECL INT t_after
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL E6POS p
              PTP {A1 10, A2 -80, A3 85, A4 5, A5 40, A6 -5}
              p = $POS_ACT
              PTP {A1 10, A2 -80, A3 85, A4 5, A5 -40, A6 -5}
              PTP p
              p.X = p.X + 10
              LIN p
              s_after = $POS_ACT.S
              t_after = $POS_ACT.T
            END
            """;

        KrlTwinController twin = Run(Source, Data);

        Joints end = twin.Arm.Joints;
        Assert.True(end.J5 > 0, $"the PTP to the position of S and T with A5 > 0 ended at {end}");
        KukaConfiguration wanted = KukaConfiguration.From(twin.Arm.Model, new Joints(10, -80, 85, 5, 40, -5));
        Assert.Equal(wanted.Status, (int)twin.Modules["prog"].Data["s_after"].Value);
        Assert.Equal(wanted.Turn, (int)twin.Modules["prog"].Data["t_after"].Value);
    }

    [Fact]
    public void PendingBlendOrNow_WithoutACorner_IsNow_BitForBit_WithACorner_IsTheCorner()
    {
        TwinArm arm = new(Twin.TwinArmForwardTests.Model, Twin.TwinArmForwardTests.Start, new TwinClock(TimeProvider.System, realTime: false))
        {
            ToolCenter = new Pose(new Vector(0, 0, 100), Rotation.Identity),
        };

        Assert.Null(arm.PendingBlendOrNow(out Joints joints, out Pose tcp));
        (Joints nowJoints, Pose nowTcp) = arm.Now;
        Assert.True(SameBits.Of(nowJoints, joints));
        Assert.True(SameBits.Of(nowTcp, tcp));

        // A LIN with a zone returns as the arm enters it: the corner is pending.
        Joints other = Twin.TwinArmForwardTests.Other;
        Pose target = arm.Model.Kinematics.Forward(other) * arm.ToolCenter;
        double seconds = TwinMotion.TrapezoidSeconds(Vector.Distance(tcp.Position, target.Position) / 1000, 0.25, 1.2); // the path's time: the tool's turn does not dominate
        arm.MoveLinear(new TwinLinearMove(target, other, 0.25, 1.2, seconds, 20, MayBlend: true), 5, "LIN C_DIS", CancellationToken.None);
        TwinBlend? corner = arm.PendingBlendOrNow(out _, out _);
        Assert.NotNull(corner);
        Assert.Same(arm.PendingBlend, corner);
        Assert.True(SameBits.Of(other, corner.CornerJoints));
    }
}

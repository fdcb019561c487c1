using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Status S and turn T of a PTP to a Cartesian position (issue 43): a POS whose S and T were never given (assigned an aggregate
/// without them, as the original Machina.NET driver does for its home) takes the solution nearest the current axes, as the
/// controller does; S and T that were given are honoured. And <c>PTP … C_PTP C_DIS</c> (PTP-CP approximation) loads.
/// </summary>
public class KrlStatusTurnTests
{
    private const string HomeProgram = """
        DEF home( )
          joint_pos_tgt = $AXIS_ACT_MEAS
          PTP joint_pos_tgt
          current_position = $POS_ACT_MES
          IK_pose_position = {X 0,Y 0,Z 0,A 0,B 0,C 0}
          IK_pose_position.X = current_position.X + 50
          IK_pose_position.Y = current_position.Y
          IK_pose_position.Z = current_position.Z - 20
          IK_pose_position.A = current_position.A
          IK_pose_position.B = current_position.B
          IK_pose_position.C = current_position.C
          PTP IK_pose_position C_PTP
          reached = $POS_ACT
        END
        """;

    private const string HomeData = """
        DEFDAT home
        DECL AXIS joint_pos_tgt
        DECL POS current_position
        DECL POS IK_pose_position
        DECL E6POS reached
        ENDDAT
        """;

    [Fact]
    public void Ptp_ToAPosWhoseStatusAndTurnWereNeverGiven_TakesTheNearestSolution()
    {
        using var twin = new KrlTwinController();
        twin.Load(("home.src", HomeProgram), ("home.dat", HomeData));
        Vector start = twin.Arm.Tcp.Position;
        KukaConfiguration before = KukaConfiguration.From(twin.Options.Model, twin.Arm.Joints);

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start + new Vector(50, 0, -20)), 0, 1e-6);
        Assert.Equal(before, KukaConfiguration.From(twin.Options.Model, twin.Arm.Joints));
        var reached = (KrlStructValue)twin.Modules["home"].Data["reached"].Value;
        Assert.Equal(before.Status, reached.Values[6]);
        Assert.Equal(before.Turn, reached.Values[7]);
    }

    [Fact]
    public void Ptp_ToAPosWithStatusAndTurnGiven_TakesOnlyThatConfiguration()
    {
        // The same position with S 'B000' and T 'B000000' given: every axis at 0° or more, which no solution of it has (A2 is negative).
        string program = HomeProgram.Replace("  PTP IK_pose_position C_PTP", "  IK_pose_position.S = 'B000'\n  IK_pose_position.T = 'B000000'\n  PTP IK_pose_position C_PTP", StringComparison.Ordinal);
        Assert.Contains("IK_pose_position.S = 'B000'", program, StringComparison.Ordinal);
        using var twin = new KrlTwinController();
        twin.Load(("home.src", program), ("home.dat", HomeData));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.StartsWith("Target not reachable: PTP {X ", twin.Error, StringComparison.Ordinal);
        Assert.Contains("no axis position with S 'B000' and T 'B000000' within the software limit switches reaches it (home.src, line 14)", twin.Error, StringComparison.Ordinal);
    }

    [Fact]
    public void Ptp_WithCptpAndCdis_Loads_AndRunsToItsTargets()
    {
        const string program = """
            DEF blend( )
              PTP $AXIS_ACT
              p = $POS_ACT
              p.Z = p.Z - 30
              PTP p C_PTP C_DIS
              p.X = p.X + 30
              LIN p
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("blend.src", program), ("blend.dat", "DEFDAT blend\nDECL E6POS p\nENDDAT\n"));
        Vector start = twin.Arm.Tcp.Position;

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start + new Vector(30, 0, -30)), 0, 1e-6);
        Assert.Contains(twin.Arm.Trace, e => e.Text == "PTP C_PTP C_DIS" && e.Line == 5);
    }

    [Theory]
    [InlineData("PTP p C_PTP C_PTP", "PTP … C_PTP takes C_DIS, C_ORI or C_VEL after it (for a LIN or CIRC that follows), not C_PTP again")]
    [InlineData("PTP p C_DIS C_PTP", "unexpected")]
    public void Ptp_WithTwoApproximationsOtherThanCptpThenAPathOne_IsRefusedAtLoad(string line, string reason)
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.Load(("blend.src", $"DEF blend( )\n  {line}\nEND\n"), ("blend.dat", "DEFDAT blend\nDECL E6POS p\nENDDAT\n")));

        Assert.Equal(2, ex.Line);
        Assert.Contains(reason, ex.Message, StringComparison.OrdinalIgnoreCase);
    }
}

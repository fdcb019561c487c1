using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// What the KRL twin keeps between statements for speed (issue 45) must not change what a program sees: a target solved by INVERSE
/// is taken again by the motion only for the same frames and start axes, and a built-in's OUT argument that an interrupt's
/// condition reads makes the interpreter look at the condition before the next statement.
/// </summary>
public class KrlKeptSolutionTests
{
    [Fact]
    public void InverseThenToolChange_TheLinSolvesAgain_TheToolCentreReachesTheTarget()
    {
        const string Source = """
            DEF prog( )
              DECL E6POS p
              DECL E6AXIS a
              DECL INT err
              PTP $AXIS_ACT
              p = $POS_ACT
              p.X = p.X + 20
              err = 0
              a = INVERSE(p, $AXIS_ACT, err)
              $TOOL = {X 0, Y 0, Z 50, A 0, B 0, C 0}
              LIN p
            END
            """;
        using var twin = new KrlTwinController();
        Pose start = twin.Arm.Tcp;
        twin.Load(("prog.src", Source));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        // The INVERSE answered for the flange with no tool; the LIN, from the same axes to the same target, needs the one with the tool.
        Vector reached = twin.Arm.Tcp.Position;
        Vector wanted = start.Position + new Vector(20, 0, 0);
        Assert.True(Vector.Distance(reached, wanted) < 1e-6, $"the tool centre is at {reached}, the target at {wanted}");
    }

    [Fact]
    public void InverseWritesAWatchedVariable_TheInterruptRunsBeforeTheNextStatement()
    {
        const string Data = """
            DEFDAT prog
              DECL INT err_g = 0
              DECL BOOL fired = FALSE
              DECL BOOL seen = FALSE
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL E6POS p
              DECL E6AXIS a
              INTERRUPT DECL 20 WHEN err_g == 1 DO caught( )
              INTERRUPT ON 20
              p = $POS_ACT
              p.X = 100000
              a = INVERSE(p, $AXIS_ACT, err_g)
              seen = fired
            END

            DEF caught( )
              fired = TRUE
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", Source), ("prog.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal(1, (int)twin.Modules["prog"].Data["err_g"].Value);
        Assert.True((bool)twin.Modules["prog"].Data["fired"].Value, "the interrupt never ran");
        Assert.True((bool)twin.Modules["prog"].Data["seen"].Value, "the interrupt ran only after the statement after INVERSE");
    }

    [Fact]
    public void InverseWithoutASolution_TheAnswerIsACopyOfTheStartAxes_WritingItLeavesTheVariable()
    {
        const string Data = """
            DEFDAT prog
              DECL E6AXIS from_axes
              DECL REAL seen[2]
            ENDDAT
            """;
        const string Source = """
            DEF prog( )
              DECL E6POS p
              DECL E6AXIS answer
              DECL INT err
              from_axes = $AXIS_ACT
              from_axes.A1 = 10
              p = $POS_ACT
              p.X = 100000
              err = 0
              answer = INVERSE(p, from_axes, err)
              answer.A1 = 77
              seen[1] = from_axes.A1
              seen[2] = err
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", Source), ("prog.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        // INVERSE reads its E6AXIS argument without a copy; the answer it gives back without a solution must still be the caller's own.
        Assert.Equal([10.0, 1.0], ((KrlArrayValue)twin.Modules["prog"].Data["seen"].Value).ToObjects().Select(v => (double)v));
    }
}

using Machina.Simulation.Krl;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Interrupts during a motion on the real-time KRL twin, as the driver's Stop and Pause use them: a flag set while a slow LIN
/// runs calls the interrupt routine at once; BRAKE holds the arm where it is; without RESUME the motion then goes on to its
/// target, with RESUME it is abandoned where the arm stands and the program goes on after the call in the declaring routine.
/// </summary>
public class KrlInterruptMotionTests
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);

    private const string Data = """
        DEFDAT prog
        DECL BOOL reached=FALSE
        DECL BOOL braked=FALSE
        DECL INT after=0
        DECL REAL held_z=0.0
        DECL REAL held_z2=0.0
        ENDDAT
        """;

    /// <summary>Main declares interrupt 30 on $FLAG[4] and calls go( ), whose slow LIN moves the TCP 100 mm down.</summary>
    private static string Program(string handler) => $$"""
        DEF prog( )
          INTERRUPT DECL 30 WHEN $FLAG[4] DO caught( )
          INTERRUPT ON 30
          PTP $AXIS_ACT
          $VEL.CP = 0.01
          go( )
          after = 1
        END

        DEF go( )
          DECL E6POS p
          p = $POS_ACT
          p.Z = p.Z - 100
          LIN p
          reached = TRUE
        END

        DEF caught( )
        {{handler}}
        END
        """;

    private static async Task<(KrlTwinController Twin, Vector Start, KrlProgramState State)> RunAndInterruptAsync(string handler)
    {
        var twin = new KrlTwinController(new KrlTwinOptions { RealTime = true });
        twin.Load(("prog.src", Program(handler)), ("prog.dat", Data));
        Vector start = twin.Arm.Tcp.Position;
        Task<KrlProgramState> run = Task.Factory.StartNew(() => twin.Run(), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        await Eventually.TrueAsync(() => Vector.Distance(twin.Arm.Tcp.Position, start) > 5 || run.IsCompleted, "the arm to leave its start", Long);
        twin.SetFlag(4, true);
        KrlProgramState state = await run.WaitAsync(Long);
        return (twin, start, state);
    }

    private static object Value(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    [Fact]
    public async Task BrakeThenResume_LeavesTheArmWhereItBraked_AndGoesOnAfterTheCallInTheDeclaringRoutine()
    {
        (KrlTwinController twin, Vector start, KrlProgramState state) = await RunAndInterruptAsync("""
              $FLAG[4] = FALSE
              BRAKE
              braked = TRUE
              RESUME
            """);

        Assert.True(state == KrlProgramState.Finished, twin.Error);
        Assert.Equal(true, Value(twin, "braked"));
        Assert.Equal(false, Value(twin, "reached"));  // go( ) was abandoned at its LIN
        Assert.Equal(1, Value(twin, "after"));         // main went on after the call of go( )
        Vector at = twin.Arm.Tcp.Position;
        Assert.True(Vector.Distance(at, start) > 5, at.ToString());
        Assert.True(Vector.Distance(at, start) < 95, $"the arm went on to {at}");
        Assert.True(Math.Abs(at.X - start.X) < 0.01 && Math.Abs(at.Y - start.Y) < 0.01, $"the LIN left its straight line: {at} from {start}");
        await Task.Delay(300);
        Assert.True(Vector.Distance(twin.Arm.Tcp.Position, at) < 1e-9, twin.Arm.Tcp.Position.ToString());
    }

    [Fact]
    public async Task BrakeWithoutResume_HoldsTheArmWhileTheRoutineRuns_ThenTheMotionGoesOnToItsTarget()
    {
        (KrlTwinController twin, Vector start, KrlProgramState state) = await RunAndInterruptAsync("""
              $FLAG[4] = FALSE
              BRAKE F
              held_z = $POS_ACT.Z
              WAIT SEC 0.3
              held_z2 = $POS_ACT.Z
            """);

        Assert.True(state == KrlProgramState.Finished, twin.Error);
        double held = (double)Value(twin, "held_z");
        Assert.Equal(held, (double)Value(twin, "held_z2"), 9);   // the arm stood while the routine waited
        Assert.True(start.Z - held > 5 && start.Z - held < 95, held.ToString(System.Globalization.CultureInfo.InvariantCulture));
        Assert.Equal(true, Value(twin, "reached"));
        Assert.Equal(1, Value(twin, "after"));
        Assert.True(twin.Arm.Tcp.Position.IsSimilar(start + new Vector(0, 0, -100), 1e-3), twin.Arm.Tcp.Position.ToString());
    }

    [Theory]
    [InlineData("DEF prog( )\n  BRAKE\nEND\n", "BRAKE is only allowed in an interrupt routine (prog.src, line 2)")]
    [InlineData("DEF prog( )\n  RESUME\nEND\n", "RESUME is only allowed in an interrupt routine (prog.src, line 2)")]
    public void BrakeAndResume_OutsideAnInterruptRoutine_StopTheProgram(string source, string error)
    {
        var twin = new KrlTwinController();
        twin.Load(("prog.src", source));

        Assert.Equal(KrlProgramState.Failed, twin.Run());
        Assert.Equal(error, twin.Error);
    }
}

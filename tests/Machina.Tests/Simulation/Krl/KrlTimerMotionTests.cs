using System.Globalization;
using Machina.Simulation.Krl;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Interrupts during a motion on the real-time KRL twin, driven by a manual clock (issue 43): a timer interrupt as published EKI
/// servers use it (<c>WHEN $TIMER_FLAG[1]==TRUE</c>, the routine setting <c>$TIMER[1] = -100</c> again) fires every 100 ms of the
/// motion with the arm part-way and the motion going on, and reads the axis speed ($VEL_AXIS_ACT % of $VEL_AXIS_MA rpm, by the gear ratio $RAT_MOT_AX, in °/s);
/// an input's rising edge stops a search motion where the arm is (BRAKE, RESUME).
/// </summary>
public class KrlTimerMotionTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    private const string TimerProgram = """
        DEF prog( )
          INTERRUPT DECL 16 WHEN $TIMER_FLAG[1]==TRUE DO tick( )
          INTERRUPT ON 16
          PTP $AXIS_ACT
          $VEL_AXIS[1] = 20
          $TIMER[1] = -100
          $TIMER_STOP[1] = FALSE
          PTP {A1 45}
          reached = TRUE
        END

        DEF tick( )
          ticks = ticks + 1
          speed = $VEL_AXIS_ACT[1] / 100.0 * $VEL_AXIS_MA[1] * $RAT_MOT_AX[1].D / $RAT_MOT_AX[1].N * 6.0
          IF ticks == 1 THEN
            first_timer = $TIMER[1]
            first_a1 = $AXIS_ACT.A1
          ENDIF
          IF ticks == 2 THEN
            second_a1 = $AXIS_ACT_MEAS.A1
            second_speed = speed
          ENDIF
          IF ticks < 5 THEN
            $TIMER[1] = -100
          ELSE
            $TIMER_STOP[1] = TRUE
          ENDIF
        END
        """;

    private const string TimerData = """
        DEFDAT prog
        DECL INT ticks=0
        DECL INT first_timer=-1
        DECL REAL first_a1=0.0
        DECL REAL second_a1=0.0
        DECL REAL speed=0.0
        DECL REAL second_speed=0.0
        DECL BOOL reached=FALSE
        ENDDAT
        """;

    private static object Value(KrlTwinController twin, string name) => twin.Modules["prog"].Data[name].Value;

    private static Task<KrlProgramState> Start(KrlTwinController twin, CancellationToken stop) =>
        Task.Factory.StartNew(() => twin.Run(cancellation: stop), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);

    private static async Task FinishAsync(KrlTwinController twin, ManualClock clock, Task<KrlProgramState> run)
    {
        while (!run.IsCompleted)
        {
            Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers > 0, Bound), "the program stalled");
            clock.AdvanceToNextTimer();
        }
        Assert.True(await run == KrlProgramState.Finished, twin.Error);
    }

    [Fact]
    public async Task TimerInterrupt_DuringAPtp_FiresEvery100ms_WithTheArmPartWay_AndTheMotionGoesOn()
    {
        var clock = new ManualClock();
        using var twin = new KrlTwinController(new KrlTwinOptions { Time = clock, RealTime = true });
        twin.Load(("prog.src", TimerProgram), ("prog.dat", TimerData));
        using var stop = new CancellationTokenSource(Bound);
        Task<KrlProgramState> run = Start(twin, stop.Token);

        for (int tick = 1; tick <= 5; tick++)
        {
            // The PTP's time and the wake of timer 1 are both set: the wake (100 ms) comes first.
            Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers == 2, Bound), $"tick {tick}: no timer wake was set during the motion");
            Assert.False(run.IsCompleted, twin.Error);
            Assert.Equal(TimeSpan.FromMilliseconds(100), clock.AdvanceToNextTimer());
        }
        await FinishAsync(twin, clock, run);

        double seconds = twin.Clock.Seconds; // the PTP's time (the BCO run takes none)
        Assert.True(seconds > 0.5, seconds.ToString(CultureInfo.InvariantCulture));
        Assert.Equal(5, Value(twin, "ticks"));
        Assert.Equal(0, Value(twin, "first_timer"));                                 // the routine ran as the timer reached 0 ms
        Assert.Equal(45 * 0.1 / seconds, (double)Value(twin, "first_a1"), 6);         // the arm 100 ms into the PTP
        Assert.Equal(45 * 0.2 / seconds, (double)Value(twin, "second_a1"), 6);
        Assert.Equal(45 / seconds, (double)Value(twin, "second_speed"), 6);            // °/s of A1 between the first two ticks
        Assert.Equal(true, Value(twin, "reached"));
        Assert.Equal(45, twin.Arm.Joints.J1, 9);
        Assert.Equal(0, clock.PendingTimers);
    }

    [Fact]
    public void TimerInterrupt_OutsideRealTime_FiresEvery100msOfProgramTime_WithTheArmPartWay_AndTheMotionGoesOn()
    {
        using var twin = new KrlTwinController(); // machina verify: program time, no clock to wait for
        twin.Load(("prog.src", TimerProgram), ("prog.dat", TimerData));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, twin.Error);
        double seconds = twin.Clock.Seconds;
        Assert.True(seconds > 0.5, seconds.ToString(CultureInfo.InvariantCulture));
        Assert.Equal(5, Value(twin, "ticks"));
        Assert.Equal(0, Value(twin, "first_timer"));
        Assert.Equal(45 * 0.1 / seconds, (double)Value(twin, "first_a1"), 6);
        Assert.Equal(45 * 0.2 / seconds, (double)Value(twin, "second_a1"), 6);
        Assert.Equal(45 / seconds, (double)Value(twin, "second_speed"), 6);
        Assert.Equal(true, Value(twin, "reached"));
        Assert.Equal(45, twin.Arm.Joints.J1, 9);
    }

    private const string WaitingProgram = """
        DEF prog( )
          INTERRUPT DECL 16 WHEN $TIMER_FLAG[1]==TRUE DO tick( )
          INTERRUPT ON 16
          PTP $AXIS_ACT
          $VEL_AXIS[1] = 20
          $TIMER[1] = -100
          $TIMER_STOP[1] = FALSE
          PTP {A1 45}
          reached = TRUE
        END

        DEF tick( )
          $TIMER_STOP[1] = TRUE
          IF brakes THEN
            BRAKE
          ENDIF
          before = $AXIS_ACT.A1
          WAIT SEC 0.2
          after = $AXIS_ACT.A1
        END
        """;

    [Theory]
    [InlineData(false, false)]
    [InlineData(false, true)]
    [InlineData(true, false)]
    [InlineData(true, true)]
    public async Task InterruptRoutine_TheArmMovesOnWhileItRuns_UnlessItBrakes_ThenTheMotionEndsAtItsTarget(bool realTime, bool brakes)
    {
        var clock = new ManualClock();
        using var twin = new KrlTwinController(realTime ? new KrlTwinOptions { Time = clock, RealTime = true } : new KrlTwinOptions());
        twin.Load(("prog.src", WaitingProgram),
            ("prog.dat", $"DEFDAT prog\nDECL BOOL brakes={(brakes ? "TRUE" : "FALSE")}\nDECL REAL before=0.0\nDECL REAL after=0.0\nDECL BOOL reached=FALSE\nENDDAT\n"));
        if (realTime)
        {
            using var stop = new CancellationTokenSource(Bound);
            await FinishAsync(twin, clock, Start(twin, stop.Token));
        }
        else
        {
            Assert.True(twin.Run() == KrlProgramState.Finished, twin.Error);
        }

        double before = (double)Value(twin, "before"), after = (double)Value(twin, "after");
        Assert.InRange(before, 1, 20); // 100 ms into the PTP
        // KUKA: the interrupted motion goes on while the routine runs (here 200 ms more of a motion at constant speed) until BRAKE.
        Assert.Equal(brakes ? before : 3 * before, after, 6);
        Assert.Equal(true, Value(twin, "reached"));
        Assert.Equal(45, twin.Arm.Joints.J1, 9);
    }

    private const string SearchProgram = """
        DEF prog( )
          INTERRUPT DECL 20 WHEN $IN[5] DO found( )
          INTERRUPT ON 20
          PTP $AXIS_ACT
          search( )
          INTERRUPT OFF 20
          after = 1
        END

        DEF search( )
          PTP {A1 45}
          reached = TRUE
        END

        DEF found( )
          BRAKE
          hit_a1 = $AXIS_ACT.A1
          RESUME
        END
        """;

    [Fact]
    public async Task InputEdge_DuringAPtp_RunsTheRoutineWhereTheArmIs_AndResumeAbandonsTheMotion()
    {
        var clock = new ManualClock();
        using var twin = new KrlTwinController(new KrlTwinOptions { Time = clock, RealTime = true });
        twin.Load(("prog.src", SearchProgram), ("prog.dat", "DEFDAT prog\nDECL INT after=0\nDECL REAL hit_a1=0.0\nDECL BOOL reached=FALSE\nENDDAT\n"));
        using var stop = new CancellationTokenSource(Bound);
        Task<KrlProgramState> run = Start(twin, stop.Token);

        Assert.True(SpinWait.SpinUntil(() => run.IsCompleted || clock.PendingTimers == 1, Bound), "the PTP did not start");
        clock.Advance(TimeSpan.FromMilliseconds(150));
        double part = twin.Arm.Joints.J1;
        twin.SetInput(5, true);
        Assert.True(await run.WaitAsync(Bound) == KrlProgramState.Finished, twin.Error);

        Assert.InRange(part, 1, 44);
        Assert.Equal(part, (double)Value(twin, "hit_a1"), 9);
        Assert.Equal(part, twin.Arm.Joints.J1, 9);
        Assert.Equal(false, Value(twin, "reached"));
        Assert.Equal(1, Value(twin, "after"));
    }
}

using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>Waits, messages, clocks and motion settings.</summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Misc() =>
    [
        Instruction("WaitTime", [Sw("InPos"), P("Time", "num")], call =>
        {
            double seconds = call.Num(1);
            if (seconds < 0)
            {
                throw ArgumentError(call, $"WaitTime: the time {RapidValues.FormatNumber(seconds)} s is negative");
            }
            RapidTwinController c = call.Machine.Task.Controller;
            RapidTask task = call.Machine.Task;
            if (!task.IsMotionTask)
            {
                // A background task (the monitor) waits on the wall clock: its period is real, it adds nothing to program time.
                WaitServingTraps(task, seconds, s => c.Clock.WaitWall(s, task.CancellationToken));
                return;
            }
            c.Arm.FinishBlend(task.CancellationToken); // the arm stops at its last waypoint before the wait counts
            WaitServingTraps(task, seconds, s => c.Clock.Wait(s, task.CancellationToken));
            c.Arm.Record(call.Line, TwinTraceKind.Wait, string.Create(CultureInfo.InvariantCulture, $"WaitTime {seconds}"));
        }),
        Instruction("TPWrite", [P("String", "string"), Opt("Num", "num"), Opt("Bool", "bool"), Opt("Pos", "pos"), Opt("Orient", "orient"), Opt("Dnum", "dnum")], call =>
        {
            string text = call.Str(0);
            for (int p = 1; p <= 5; p++)
            {
                if (call.Has(p))
                {
                    text += RapidValues.ToText(call.Value(p));
                }
            }
            call.Machine.Task.Controller.Pendant.Log(call.Machine.Task.Controller.TaskLabel(call.Machine.Task) + text);
            call.Machine.Task.Controller.Arm.Record(call.Line, TwinTraceKind.Message, text);
        }),
        Instruction("TPErase", [], _ => { }),
        Instruction("ClkStart", [P("Clock", "clock", true)], call =>
        {
            var clock = (RapidClock)call.Value(0);
            clock.StartedAt ??= ClockSeconds(call.Machine.Task.Controller);
        }),
        Instruction("ClkStop", [P("Clock", "clock", true)], call =>
        {
            var clock = (RapidClock)call.Value(0);
            if (clock.StartedAt is { } start)
            {
                clock.Accumulated += ClockSeconds(call.Machine.Task.Controller) - start;
                clock.StartedAt = null;
            }
        }),
        Instruction("ClkReset", [P("Clock", "clock", true)], call =>
        {
            var clock = (RapidClock)call.Value(0);
            clock.Accumulated = 0;
            clock.StartedAt = clock.StartedAt is null ? null : ClockSeconds(call.Machine.Task.Controller);
        }),
        Function("ClkRead", "num", [P("Clock", "clock", true), Sw("HighRes")], call =>
        {
            var clock = (RapidClock)call.Value(0);
            double seconds = clock.Accumulated + (clock.StartedAt is { } start ? ClockSeconds(call.Machine.Task.Controller) - start : 0);
            return call.Has(1) ? Math.Round(seconds, 6) : Math.Round(seconds, 3);
        }),
        Function("Present", "bool", [P("OptPar", null, true)], call =>
        {
            try
            {
                call.Value(0);
                return true;
            }
            catch (RapidRuntimeException ex) when (ex.ErrorNumber == RapidErrorNumbers.NotPres)
            {
                return false;
            }
        }),
    ];

    /// <summary>The longest a wait sleeps before it looks for traps to run, when the task ordered timer or signal interrupts (seconds).</summary>
    private const double TrapLatency = 0.05;

    /// <summary>
    /// What a <c>clock</c> counts, in seconds from an arbitrary start: in real time the controller's time source, so every wait
    /// counts whichever task waits (a background task's WaitTime and a socket wait add no program time); otherwise the program
    /// time, which a run without real time has instead.
    /// </summary>
    private static double ClockSeconds(RapidTwinController c) =>
        c.Clock.RealTime ? c.Clock.Time.GetTimestamp() / (double)c.Clock.Time.TimestampFrequency : c.Clock.Seconds;

    /// <summary>
    /// Waits <paramref name="seconds"/> with <paramref name="wait"/>; when the task ordered timer or signal interrupts, in slices that end
    /// when a timer is due or after <see cref="TrapLatency"/>, running the queued traps between them (a trap interrupts a wait).
    /// </summary>
    private static void WaitServingTraps(RapidTask task, double seconds, Action<double> wait)
    {
        if (!task.HasEventOrders)
        {
            wait(seconds);
            return;
        }
        double left = seconds;
        while (left > 0)
        {
            double slice = Math.Min(left, task.NextTimerWithin(TrapLatency));
            wait(slice);
            left -= slice;
            task.RunPendingTraps();
        }
    }

    private static IEnumerable<RapidBuiltin> Settings() =>
    [
        Instruction("ConfL", [Sw("On"), Sw("Off")], call => call.Machine.Task.ConfL = !call.Has(1)),
        Instruction("ConfJ", [Sw("On"), Sw("Off")], call => call.Machine.Task.ConfJ = !call.Has(1)),
        Instruction("SingArea", [Sw("Wrist"), Sw("LockAxis4"), Sw("Off")], call => call.Machine.Task.SingAreaWrist = call.Has(0)),
        Instruction("CirPathMode", [Sw("PathFrame"), Sw("ObjectFrame"), Sw("CirPointOri"), Sw("Wrist45"), Sw("Wrist46"), Sw("Wrist56")], _ => { }),
        Instruction("VelSet", [P("Override", "num"), P("Max", "num")], call =>
        {
            double overridePercent = call.Num(0), max = call.Num(1);
            if (overridePercent <= 0 || max <= 0)
            {
                throw ArgumentError(call, "VelSet: the override and the largest speed must be positive");
            }
            call.Machine.Task.SpeedOverride = overridePercent;
            call.Machine.Task.MaxSpeed = max;
        }),
        Instruction("AccSet", [P("Acc", "num"), P("Ramp", "num")], call =>
        {
            double acc = call.Num(0);
            if (acc < 20 || acc > 100)
            {
                throw ArgumentError(call, $"AccSet: the acceleration {RapidValues.FormatNumber(acc)} % is outside 20..100 %");
            }
            call.Machine.Task.AccelerationPercent = acc;
        }),
        Instruction("WorldAccLim", [Opt("On", "num"), Sw("Off")], call =>
        {
            if (call.Has(0))
            {
                double limit = call.Num(0);
                if (limit <= 0)
                {
                    throw ArgumentError(call, "WorldAccLim: the acceleration limit must be positive");
                }
                call.Machine.Task.AccelerationLimit = limit;
            }
            else
            {
                call.Machine.Task.AccelerationLimit = null;
            }
        }),
    ];
}

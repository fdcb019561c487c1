using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>Outputs, signals and the inputs a WAIT FOR waits on.</summary>
internal sealed partial class KrlTwinController
{
    /// <summary>
    /// The controller's IO as the twins share it: the values of $IN, $OUT, $ANIN and $ANOUT (banks of those names, which KRL reads
    /// and writes as arrays, <see cref="KrlSignalArray"/>) and what a WAIT FOR sleeps on (its change count and wake-up). Flags
    /// ($FLAG) are the program's own markers, a system variable.
    /// </summary>
    public TwinIo Io { get; } = new();

    /// <summary>How many times a program wrote a variable an interrupt's condition reads (see <see cref="KrlCell.Watch"/>).</summary>
    public KrlWatchedWrites WatchedWrites { get; } = new();

    /// <summary>How many times inputs, flags or channels changed (a WAIT FOR compares it before it sleeps).</summary>
    public long InputsVersion => Io.Version;

    /// <summary>True while something outside the program can change what a WAIT FOR waits on (an open EthernetKRL channel).</summary>
    public bool HasExternalInputs => EkiOpenChannels > 0;

    /// <summary>Tells waiting programs that an input, a flag or a channel changed.</summary>
    public void InputsChanged()
    {
        Io.Changed();
        Arm.Wake(); // a motion under way serves the interrupts whose condition this may have made TRUE
    }

    /// <summary>
    /// Sleeps until something changes after <paramref name="version"/>: an input, a flag, a channel, or a program's write of a
    /// variable a WAIT FOR's condition reads (<see cref="KrlWaitWake"/>). When <paramref name="looksAtTime"/> (the condition, or an
    /// interrupt served while it waits, reads a timer or something else that changes without a wake-up) and a timer runs
    /// ($TIMER_STOP FALSE), it returns after one interpreter cycle, as a KRC looks again: outside real-time mode that cycle is
    /// program time (at once when nothing outside the program can change anything, else the time waited for the outside, at most
    /// one cycle), so the timers move by at most one cycle between two looks and a program's timer values do not depend on the
    /// machine's load. Otherwise a running timer's time passes while it sleeps (program time outside real-time mode: the time waited).
    /// </summary>
    public void WaitForInputs(long version, bool looksAtTime, CancellationToken cancellation)
    {
        try
        {
            while (InputsVersion == version)
            {
                bool timing = TimersRunning();
                bool external = HasExternalInputs;
                if (!external && !timing)
                {
                    throw new KrlRuntimeException("WAIT FOR can never end: nothing outside the program changes its condition on this twin (no channel open, no timer running)");
                }
                bool cycles = timing && looksAtTime;
                if (cycles && !Clock.RealTime && !external)
                {
                    Clock.Wait(InterpreterCycle.TotalSeconds, cancellation);
                    return;
                }
                long started = Options.Time.GetTimestamp();
                // Without the cycle's look, only a timer that starts (a condition that reads one) or stops (the last source of a
                // change gone) goes unsignalled: with a channel open and a condition woken on change, nothing needs a look.
                Io.WaitForChange(version, cycles ? InterpreterCycle : external && !looksAtTime ? WokenWaitCheck : TimeSpan.FromMilliseconds(100), cancellation);
                if (timing && !Clock.RealTime)
                {
                    double waited = Options.Time.GetElapsedTime(started).TotalSeconds;
                    Clock.Add(cycles ? Math.Min(waited, InterpreterCycle.TotalSeconds) : waited);
                }
                if (cycles)
                {
                    return;
                }
            }
        }
        finally
        {
            Interlocked.Increment(ref _waitForLooks);
        }
    }

    /// <summary>How long a WAIT FOR woken on change sleeps, with a channel open, before it looks whether it can still end.</summary>
    private static readonly TimeSpan WokenWaitCheck = TimeSpan.FromMinutes(1);

    private bool TimersRunning() => Array.Exists(((KrlArrayValue)Motion.TimerStop.Value).Objects, s => !(bool)s);

    /// <summary>Sets digital input <c>$IN[number]</c> (1-based), as a sensor wired to it would, and wakes a waiting program.</summary>
    public void SetInput(int number, bool value)
    {
        Io.SetBit("$IN", number - 1, value);
        InputsChanged();
    }

    /// <summary>Sets analog input <c>$ANIN[number]</c> (1-based), as a sensor wired to it would, and wakes a waiting program.</summary>
    public void SetAnalogInput(int number, double value)
    {
        Io.SetNumber("$ANIN", number - 1, value);
        InputsChanged();
    }

    /// <summary>$FLAG's cell, found once (a channel's reader sets a flag for every document it receives).</summary>
    private KrlCell FlagCell => _flagCell ??= Environment.System["$FLAG"];

    private KrlCell? _flagCell;

    /// <summary>Sets flag <paramref name="number"/> (1-based) and wakes a waiting program.</summary>
    public void SetFlag(int number, bool value)
    {
        object[] flags = ((KrlArrayValue)FlagCell.Value).Objects;
        flags[number - 1] = KrlValues.Box(value);
        InputsChanged();
    }

    private object Out(int number) => KrlValues.Box(Io.GetBit("$OUT", number - 1));

    /// <summary>An element of $OUT or $ANOUT was written (index -1: the whole array).</summary>
    public void OutputWritten(string array, int index)
    {
        if (index < 0)
        {
            return;
        }
        object value = Environment.System[array].Signals!.Get(index);
        if (array == "$ANOUT" && KrlValues.ToReal(value) is < -1 or > 1)
        {
            throw new KrlRuntimeException("Value assignment inadmissible: $ANOUT takes values from -1 to 1");
        }
        Arm.Record(TraceLine(), TwinTraceKind.Output, FormattableString.Invariant($"{array}[{index + 1}] = {KrlValues.Format(value)}"));
    }

    private void SignalWritten(string name, int output)
    {
        var cell = Environment.Signals[name];
        Io.SetBit("$OUT", output - 1, (bool)cell.Box[0]);
        Arm.Record(TraceLine(), TwinTraceKind.Output, $"{name} = {KrlValues.Format(cell.Box[0])}");
    }
}

namespace Machina.Simulation.Twin;

/// <summary>
/// Motions outside real time that interrupts can wake (KRL: a timer's interrupt in <c>machina verify</c>): the motion runs in
/// program time, the arm part-way as the program time passes, and stops being one step at the moments <see cref="NextWake"/>
/// gives, where its interrupts are served (<see cref="Serve"/>) while it goes on, as in real time.
/// </summary>
internal sealed partial class TwinArm
{
    /// <summary>A motion in program time: what it does, the program time it started at, and where a BRAKE stopped it (seconds into it).</summary>
    private sealed class PacedMotion(Motion motion, double start)
    {
        public Motion Motion { get; } = motion;

        public double Start { get; set; } = start;

        public double? BrakedAt { get; set; }

        /// <summary>Where a motion of its interrupt routine left the arm (after its BRAKE), or null.</summary>
        public Joints? StandsAt { get; set; }

        /// <summary>The joints at program time <paramref name="now"/>.</summary>
        public Joints At(double now) => StandsAt ?? Motion.At(BrakedAt ?? now - Start);
    }

    private PacedMotion? _paced;

    /// <summary>
    /// Outside real time, the program time in seconds from now to the next moment a motion must be woken to serve its interrupts
    /// (a timer reaching 0), or a negative number for none; null (the default): a motion is one step of program time.
    /// </summary>
    public Func<double>? NextWake { get; set; }

    /// <summary>
    /// Moves to <paramref name="target"/> in <paramref name="seconds"/> of program time, stopping at each wake to serve the
    /// interrupts while the motion goes on (a <see cref="Brake"/> in the routine holds it until the routine returns; the rest then
    /// goes straight from where the arm stands). A motion run by an interrupt routine brakes the one it interrupted first.
    /// </summary>
    private bool MovePaced<TPath>(Joints target, double seconds, int line, string text, CancellationToken cancellation, Joints? traced, bool trace, bool linear,
        in TPath path, TwinArc? arc)
        where TPath : struct, ITwinPath
    {
        PacedMotion? outer;
        lock (_gate)
        {
            outer = _paced;
            BrakePaced();
        }
        if (outer is null && NextWake!() is var firstWake && (firstWake < 0 || firstWake >= seconds))
        {
            // Nothing wakes it before it ends (the usual case: no timer runs) and it interrupts no motion: one step of program
            // time, as a motion without wakes, with no motion in program time to make (the tool poses it would solve at its ends).
            return MoveInOneStep(target, seconds, line, text, cancellation, traced, trace);
        }
        var paced = new PacedMotion(new Motion(Joints, target, 0, seconds, linear || arc is not null ? this : null, path.Make(), arc), Clock.Seconds);
        lock (_gate)
        {
            _paced = paced;
        }
        try
        {
            while (true)
            {
                double left = paced.Motion.Seconds - (Clock.Seconds - paced.Start);
                double wake = NextWake!();
                if (wake < 0 || wake >= left)
                {
                    Clock.Wait(left, cancellation);
                    break;
                }
                Clock.Wait(wake, cancellation);
                Serve?.Invoke(); // the routine runs while the arm moves on in program time
                lock (_gate)
                {
                    if (paced.BrakedAt is { } at)
                    {
                        // Braked in the routine: the rest goes on from where the arm stands, now.
                        double rest = paced.Motion.Seconds - at;
                        paced = new PacedMotion(new Motion(paced.At(0), target, 0, rest, paced.Motion.Cartesian, null, null), Clock.Seconds);
                        _paced = paced;
                    }
                }
            }
            lock (_gate)
            {
                _paced = outer;
                _joints = target;
                if (outer is not null)
                {
                    outer.StandsAt = target;
                }
            }
            if (trace)
            {
                Record(line, TwinTraceKind.Motion, text, traced);
            }
            return true;
        }
        finally
        {
            lock (_gate)
            {
                if (ReferenceEquals(_paced, paced))
                {
                    // Ended early (RESUME, cancellation): the arm stays where the program time had taken it.
                    _joints = paced.At(Clock.Seconds);
                    _paced = outer;
                    if (outer is not null)
                    {
                        outer.StandsAt = _joints;
                    }
                }
            }
        }
    }

    /// <summary>Brakes the motion in program time under way (call under the gate); false when none runs.</summary>
    private bool BrakePaced()
    {
        if (_paced is not { } paced)
        {
            return false;
        }
        paced.BrakedAt ??= Math.Min(Clock.Seconds - paced.Start, paced.Motion.Seconds);
        return true;
    }
}

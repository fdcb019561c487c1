namespace Machina.Simulation.Twin;

/// <summary>
/// The motion path of the arm as a controller's path planner holds it: while a motion runs the arm is part-way (at constant speed,
/// straight in joint space or, for a linear or circular motion, along the tool's straight line or arc), a hold (RAPID StopMove) stops it where it
/// is until released (StartMove), a cleared path (ClearPath)
/// ends the motion where the arm stands (and drops a pending blend), and a wake lets the moving task serve its interrupts.
/// </summary>
internal sealed partial class TwinArm
{
    private Motion? _moving;
    private TaskCompletionSource? _held;
    private CancellationTokenSource _interrupt = new();
    private bool _clear;
    private double _heldAfter;

    /// <summary>
    /// A motion under way: from, to, when it started (timestamp of the clock's time provider) and how long it takes. A joint motion
    /// is straight in joint space; a Cartesian one (<paramref name="Cartesian"/>: the arm whose tool moves) keeps the tool centre point
    /// on the straight line, or on the <paramref name="Arc"/> from the part <paramref name="ArcFrom"/> of it already behind (after a hold
    /// or a wake), and turns its orientation evenly (an arc's as it says), the joints solved at each point nearest to the joint-space
    /// interpolation; a motion with its own <paramref name="Path"/> (a blend: fraction of the way to joints) follows it. The tool poses
    /// at the start and the end are computed once, when the motion is made, so that reading the joints while it runs solves one pose only.
    /// </summary>
    private sealed record Motion(Joints From, Joints To, long Started, double Seconds, TwinArm? Cartesian = null, Func<double, Joints>? Path = null,
        TwinArc? Arc = null, double ArcFrom = 0)
    {
        private readonly Pose _tool = Cartesian?.ToolCenter ?? Pose.Identity;
        private readonly Pose _start = Cartesian is null || Arc is not null ? Pose.Identity : Cartesian.FlangeAt(From) * Cartesian.ToolCenter;
        private readonly Pose _end = Cartesian is null || Arc is not null ? Pose.Identity : Cartesian.FlangeAt(To) * Cartesian.ToolCenter;

        /// <summary>The part of the whole arc behind the arm <paramref name="elapsed"/> seconds after this motion started.</summary>
        public double ArcFractionAt(double elapsed) => ArcFrom + (1 - ArcFrom) * (Seconds > 0 ? Math.Clamp(elapsed / Seconds, 0, 1) : 1);

        /// <summary>The joints <paramref name="elapsed"/> seconds after the start.</summary>
        public Joints At(double elapsed)
        {
            double f = Seconds > 0 ? Math.Clamp(elapsed / Seconds, 0, 1) : 1;
            if (f >= 1)
            {
                return To;
            }
            if (f <= 0)
            {
                return From;
            }
            if (Path is not null)
            {
                return Path(f);
            }
            double[] a = From.ToArray(), b = To.ToArray();
            var straight = new Joints(a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f,
                a[3] + (b[3] - a[3]) * f, a[4] + (b[4] - a[4]) * f, a[5] + (b[5] - a[5]) * f);
            if (Cartesian is not { } arm)
            {
                return straight;
            }
            Pose tcp = Arc is { } arc
                ? arc.At(ArcFrom + (1 - ArcFrom) * f)
                : new Pose(_start.Position + (_end.Position - _start.Position) * f, KinematicChecks.Slerp(_start.Rotation, _end.Rotation, f));
            return arm.Model.Kinematics.Closest(tcp * _tool.Inverse(), straight) ?? straight;
        }
    }

    /// <summary>
    /// True: real-time motions are interpolated (the arm is part-way while it moves) and obey <see cref="Hold"/>, <see cref="Release"/>
    /// and <see cref="ClearPath"/>. False (the default): the arm is at the start until a motion's time has passed, then at its target.
    /// </summary>
    public bool Interpolates { get; init; }

    /// <summary>True while the motion is held (<see cref="Hold"/>).</summary>
    public bool IsHeld
    {
        get
        {
            lock (_gate)
            {
                return _held is not null;
            }
        }
    }

    /// <summary>Holds the motion (RAPID StopMove): a motion under way stops where the arm is; none starts until <see cref="Release"/>. False when already held.</summary>
    public bool Hold()
    {
        lock (_gate)
        {
            if (_held is not null)
            {
                return false;
            }
            _held = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            if (_moving is { } moving)
            {
                // The arm stands where it is now, whenever the moving task gets to it.
                _heldAfter = Math.Min(Clock.Time.GetElapsedTime(moving.Started).TotalSeconds, moving.Seconds);
                _joints = moving.At(_heldAfter);
                _moving = null;
            }
            _interrupt.Cancel();
            return true;
        }
    }

    /// <summary>Ends <see cref="Hold"/> (RAPID StartMove): a held motion goes on from where it stopped. False when not held.</summary>
    public bool Release()
    {
        TaskCompletionSource? held;
        lock (_gate)
        {
            held = _held;
            _held = null;
        }
        held?.TrySetResult();
        return held is not null;
    }

    /// <summary>Clears the path (RAPID ClearPath): the motion under way ends where the arm stands, without reaching its target.</summary>
    public void ClearPath()
    {
        lock (_gate)
        {
            _clear = _moving is not null || _held is not null;
            _blend = null; // the corner it would have rounded is cleared with the path
            _interrupt.Cancel();
        }
    }

    /// <summary>Wakes a motion under way so that its task serves an interrupt (the motion goes on).</summary>
    public void Wake()
    {
        lock (_gate)
        {
            _interrupt.Cancel();
        }
    }

    /// <summary>
    /// A real-time motion along the path: <paramref name="target"/> in <paramref name="seconds"/>, held and released, ended early by a
    /// cleared path; <see cref="Serve"/> runs each time the motion is woken (an exception it throws leaves the arm where it stands).
    /// </summary>
    private bool MoveAlongPath<TPath>(Joints target, double seconds, int line, string text, CancellationToken cancellation, Joints? traced, bool trace, bool linear,
        in TPath pathSource, TwinArc? arc)
        where TPath : struct, ITwinPath
    {
        Func<double, Joints>? path = pathSource.Make();
        if (MovesWhileServing)
        {
            Brake(); // a motion an interrupt routine runs stops the one it interrupted first (KUKA: BRAKE before a motion there)
        }
        Joints from = Joints;
        double left = seconds;
        double arcFrom = 0; // the part of the arc behind the arm (a hold or a wake cut the motion short: the rest goes on along the arc)
        _clear = false;
        while (true)
        {
            CancellationToken interrupt;
            Task? held;
            lock (_gate)
            {
                if (_interrupt.IsCancellationRequested)
                {
                    _interrupt.Dispose();
                    _interrupt = new CancellationTokenSource();
                }
                interrupt = _interrupt.Token;
                held = _held?.Task;
            }
            Serve?.Invoke();
            lock (_gate)
            {
                if (_clear)
                {
                    _clear = false;
                    Record(line, TwinTraceKind.Motion, text + " (path cleared)");
                    return false;
                }
            }
            using var both = CancellationTokenSource.CreateLinkedTokenSource(cancellation, interrupt);
            if (held is not null)
            {
                try
                {
                    TwinWait.For(held, both.Token);
                }
                catch (OperationCanceledException) when (!cancellation.IsCancellationRequested)
                {
                    // Woken while held: serve the interrupt, then wait again.
                }
                continue;
            }
            var motion = new Motion(from, target, Clock.Time.GetTimestamp(), left, linear || arc is not null ? this : null, path, arc, arcFrom);
            lock (_gate)
            {
                _moving = motion;
            }
            try
            {
                WaitMoving(motion, cancellation, both.Token); // the motion takes its time; the caller counts it as program time
                lock (_gate)
                {
                    _moving = null;
                    _joints = target;
                }
                Clock.Add(left);
                if (trace)
                {
                    Record(line, TwinTraceKind.Motion, text, traced);
                }
                return true;
            }
            catch (OperationCanceledException) when (!cancellation.IsCancellationRequested)
            {
                double elapsed;
                lock (_gate)
                {
                    if (ReferenceEquals(_moving, motion))
                    {
                        elapsed = Math.Min(Clock.Time.GetElapsedTime(motion.Started).TotalSeconds, left);
                        _moving = null;
                        _joints = motion.At(elapsed);
                    }
                    else
                    {
                        elapsed = _heldAfter; // a hold stopped it and put the arm where it stands
                    }
                    from = _joints;
                }
                Clock.Add(elapsed);
                arcFrom = motion.ArcFractionAt(elapsed);
                left -= elapsed;
                path = null; // cut short: the rest of the way goes straight (or on along the arc) from where the arm stands
            }
            finally
            {
                lock (_gate)
                {
                    if (ReferenceEquals(_moving, motion))
                    {
                        if (MovesWhileServing)
                        {
                            // An interrupt routine that ends the motion (RESUME) leaves the arm where the motion had taken it.
                            _joints = motion.At(Math.Min(Clock.Time.GetElapsedTime(motion.Started).TotalSeconds, left));
                        }
                        _moving = null;
                    }
                }
            }
        }
    }

    /// <summary>What the moving task does when its motion is woken (RAPID: serve its interrupts); null: nothing.</summary>
    public Action? Serve { get; set; }
}

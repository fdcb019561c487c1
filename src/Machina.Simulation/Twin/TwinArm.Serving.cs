namespace Machina.Simulation.Twin;

/// <summary>
/// Interrupts served while the motion goes on (KUKA: the interrupted motion continues while the interrupt routine runs, until
/// a BRAKE in it stops the arm; when the routine returns, a braked motion goes on from where the arm stands), in real time on
/// the clock's time source and, outside real time, in program time (see TwinArm.Paced.cs).
/// </summary>
internal sealed partial class TwinArm
{
    /// <summary>
    /// True: a wake serves the interrupts (<see cref="Serve"/>) while the motion under way goes on, until <see cref="Brake"/> stops
    /// it (KRL). False (the default, RAPID and URScript): the arm stands where the motion was while they are served.
    /// </summary>
    public bool MovesWhileServing { get; init; }

    /// <summary>
    /// Stops the motion under way where the arm is now (KRL BRAKE, in an interrupt routine): it goes on from there, to its target,
    /// when the routine returns. False when no motion runs.
    /// </summary>
    public bool Brake()
    {
        lock (_gate)
        {
            if (_moving is { } moving)
            {
                _heldAfter = Math.Min(Clock.Time.GetElapsedTime(moving.Started).TotalSeconds, moving.Seconds);
                _joints = moving.At(_heldAfter);
                _moving = null;
                return true;
            }
            return BrakePaced();
        }
    }

    /// <summary>
    /// Waits until <paramref name="motion"/> has taken its time. With <see cref="MovesWhileServing"/>, each wake serves the
    /// interrupts while the motion goes on, then waits for the rest of its time; otherwise (and after a hold, a cleared path or a
    /// <see cref="Brake"/>) the wake ends the wait with <see cref="OperationCanceledException"/>, as does cancellation.
    /// </summary>
    private void WaitMoving(Motion motion, CancellationToken cancellation, CancellationToken first)
    {
        CancellationToken token = first;
        CancellationTokenSource? linked = null;
        try
        {
            while (true)
            {
                try
                {
                    // The whole time at first (as a motion that no wake serves waits), after a wake what is left of it.
                    double rest = linked is null ? motion.Seconds : motion.Seconds - Clock.Time.GetElapsedTime(motion.Started).TotalSeconds;
                    if (rest > 0)
                    {
                        Clock.WaitAside(rest, token);
                    }
                    return;
                }
                catch (OperationCanceledException) when (!cancellation.IsCancellationRequested && MovesWhileServing && IsWakeOf(motion))
                {
                    CancellationToken interrupt;
                    lock (_gate)
                    {
                        _interrupt.Dispose();
                        _interrupt = new CancellationTokenSource();
                        interrupt = _interrupt.Token;
                    }
                    linked?.Dispose();
                    linked = CancellationTokenSource.CreateLinkedTokenSource(cancellation, interrupt);
                    token = linked.Token;
                    Serve?.Invoke(); // the routine runs while the arm moves on
                    if (!IsWakeOf(motion))
                    {
                        throw new OperationCanceledException(token); // braked, held or cleared meanwhile: the mover stops it
                    }
                }
            }
        }
        finally
        {
            linked?.Dispose();
        }
    }

    /// <summary>True while <paramref name="motion"/> runs on, neither braked, held nor cleared: a wake only.</summary>
    private bool IsWakeOf(Motion motion)
    {
        lock (_gate)
        {
            return ReferenceEquals(_moving, motion) && !_clear && _held is null;
        }
    }
}

using System.Globalization;
using System.Threading.Channels;

namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    /// <summary>The longest motion or wait a controller can time: <see cref="Task.Delay(TimeSpan)"/> stops at about 49.7 days.</summary>
    internal static readonly TimeSpan MaxDuration = TimeSpan.FromMilliseconds(uint.MaxValue - 1);

    /// <summary>Largest coordinate a target may have, in mm (1 km): anything beyond is a unit mistake, not a robot target.</summary>
    internal const double MaxCoordinate = 1e6;

    private TaskCompletionSource? _halted;
    private CancellationTokenSource _haltSource = new();

    /// <summary>The state after <paramref name="request"/> from <paramref name="state"/>; throws <see cref="VirtualRefusalException"/> for what the robot cannot do.</summary>
    private protected abstract VirtualStep Plan(TState state, object request);

    /// <summary>Acknowledges an executed request (and whatever else the brand's driver sends then); false ends the driver program.</summary>
    private protected abstract Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token);

    /// <summary>
    /// Called for a request the robot refused (nothing of it ran, the robot is where the previous one left it). True when the
    /// brand's driver reports the failure and stops its program there, as a real controller does: the request is neither logged
    /// as executed nor acknowledged, and nothing after it runs. False (the default) logs it and acknowledges it as before.
    /// </summary>
    private protected virtual Task<bool> StopsOnRefusalAsync(object request, int id, VirtualRefusalException refusal, CancellationToken token) =>
        Task.FromResult(false);

    /// <summary>
    /// True for a request a restart lost while the execution loop waited for the brand's driver to run it (the KRL twin's): it
    /// did not run, is neither logged nor acknowledged.
    /// </summary>
    private protected virtual bool LostInRestart(object request) => false;

    /// <summary>True for a request the brand's driver will skip (a UR program replaced since it was read); it is not logged as executed.</summary>
    private protected virtual bool IsStale(object request) => false;

    /// <summary>
    /// Called when <paramref name="request"/> is refused: true when the brand's program stops there (a UR runtime error), so the
    /// request is not logged as executed; false (the default) when the driver logs the refusal and goes on.
    /// </summary>
    private protected virtual bool FailsProgram(object request, string reason) => false;

    private async Task ExecuteRequestsAsync(CancellationToken token)
    {
        var reader = _buffer.Reader;
        try
        {
            while (await reader.WaitToReadAsync(token).ConfigureAwait(false))
            {
                await WhileStoppedAsync(token).ConfigureAwait(false);
                if (!reader.TryRead(out var queued))
                {
                    continue;
                }
                if (IsLost(queued.Generation))
                {
                    Dropped(queued.Request);
                    continue;
                }
                var (runs, refusal) = await ExecuteAsync(queued.Request, token).ConfigureAwait(false);
                if (LostInRestart(queued.Request))
                {
                    Interlocked.Increment(ref _requestsLost);
                    continue;
                }
                if (refusal is not null && await StopsOnRefusalAsync(queued.Request, queued.Id, refusal, token).ConfigureAwait(false))
                {
                    Interlocked.Increment(ref _requestsExecuted);
                    return;
                }
                if (!await CompleteAsync(queued.Request, queued.Id, runs, token).ConfigureAwait(false))
                {
                    return;
                }
            }
        }
        catch (Exception e) when (e is OperationCanceledException or ChannelClosedException)
        {
            // Stopping.
        }
    }

    /// <summary>
    /// What follows a request the robot is done with: logs it executed (unless its driver skipped it), counts it, then runs
    /// <see cref="AfterExecutedAsync"/> (an answer that fails is recorded, and the controller serves on). False ends the driver program.
    /// </summary>
    private async Task<bool> CompleteAsync(object request, int id, bool runs, CancellationToken token)
    {
        if (runs)
        {
            LogExecuted(id);
        }
        Interlocked.Increment(ref _requestsExecuted);
        // Before the acknowledgement goes out: whoever sees it also sees the pause it may start.
        CountTowardsPause();
        try
        {
            return await AfterExecutedAsync(request, id, token).ConfigureAwait(false);
        }
        catch (Exception e) when (e is not OperationCanceledException)
        {
            RecordError($"answering request {id.ToString(CultureInfo.InvariantCulture)} failed: {e.Message}");
            return true;
        }
    }

    /// <summary>
    /// Executes one request: plans it, refuses (and logs) what cannot run, and waits for its motion on the controller's clock.
    /// A protective stop interrupts the motion where the robot is; once released the same request runs again from there.
    /// Runs is false when the brand's driver skipped it (<see cref="IsStale"/> when it was last planned): it does not enter the
    /// execution log. Refusal is why the robot could not run it (logged), or null.
    /// </summary>
    private async Task<(bool Runs, VirtualRefusalException? Refusal)> ExecuteAsync(object request, CancellationToken token)
    {
        while (true)
        {
            await WhileHaltedAsync(token).ConfigureAwait(false);
            bool runs = !IsStale(request);
            TState from;
            CancellationToken halt;
            lock (Gate)
            {
                from = _state;
                halt = _haltSource.Token;
            }
            VirtualStep step;
            TimeSpan duration;
            try
            {
                step = Plan(from, request);
                duration = Check(step);
            }
            catch (Exception e) when (e is VirtualRefusalException or ArgumentException or ArithmeticException or InvalidOperationException)
            {
                RecordError("refused: " + e.Message);
                // UR's program stops in place (FailsProgram: the controller goes on to the next program); ABB's and KUKA's driver
                // reports the failure and stops (StopsOnRefusalAsync, asked by the caller).
                return (runs && !FailsProgram(request, e.Message), e as VirtualRefusalException ?? new VirtualRefusalException(e.Message));
            }
            if (duration > TimeSpan.Zero)
            {
                lock (Gate)
                {
                    _motion = new VirtualMotion(from, step.State, Clock.GetTimestamp(), duration, step.InJointSpace, Model);
                }
                using var both = CancellationTokenSource.CreateLinkedTokenSource(token, halt);
                try
                {
                    await Task.Delay(duration, Clock, both.Token).ConfigureAwait(false);
                }
                catch (OperationCanceledException) when (!token.IsCancellationRequested)
                {
                    lock (Gate)
                    {
                        _state = (TState)_motion!.At(Clock, Clock.GetTimestamp());
                        _motion = null;
                    }
                    continue;
                }
            }
            lock (Gate)
            {
                _state = (TState)step.State;
                _motion = null;
            }
            return (runs, null);
        }
    }

    /// <summary>The real duration of a planned step, or a refusal when its target or its duration cannot be executed.</summary>
    private TimeSpan Check(in VirtualStep step)
    {
        var s = step.State;
        RequirePlace(s.Position);
        if (!s.Joints.IsFinite)
        {
            throw new VirtualRefusalException($"the joints {s.Joints} are not numbers.");
        }
        double seconds = step.Seconds / _options.SpeedFactor;
        if (double.IsNaN(seconds) || seconds < 0)
        {
            throw new VirtualRefusalException("the instruction has no valid duration.");
        }
        if (seconds > MaxDuration.TotalSeconds)
        {
            throw new VirtualRefusalException($"the instruction would take {Num.G(step.Seconds)} s, longer than the {Num.G(Math.Floor(MaxDuration.TotalDays * 10) / 10)} days a controller can time.");
        }
        return _options.InstantExecution || seconds == 0 ? TimeSpan.Zero : TimeSpan.FromSeconds(seconds);
    }

    /// <summary>
    /// Stops the robot where it is, as a protective stop does: the motion in progress ends at its current point and nothing
    /// more executes until <see cref="ReleaseHalt"/>; the interrupted request then runs again from there. False when already halted.
    /// </summary>
    private protected bool Halt()
    {
        CancellationTokenSource source;
        lock (Gate)
        {
            if (_halted is not null)
            {
                return false;
            }
            _halted = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            source = _haltSource;
            if (_motion is not null)
            {
                _state = (TState)_motion.At(Clock, Clock.GetTimestamp());
                _motion = new VirtualMotion(_state, _state, Clock.GetTimestamp(), TimeSpan.Zero, false, Model);
            }
        }
        source.Cancel();
        return true;
    }

    /// <summary>Ends <see cref="Halt"/>: execution continues with the interrupted request. False when not halted.</summary>
    private protected bool ReleaseHalt()
    {
        TaskCompletionSource halted;
        lock (Gate)
        {
            if (_halted is null)
            {
                return false;
            }
            halted = _halted;
            _halted = null;
            // The old source stays cancelled (a linked source may still be watching it); it holds no timer to dispose.
            _haltSource = new CancellationTokenSource();
        }
        halted.TrySetResult();
        return true;
    }

    /// <summary>True between <see cref="Halt"/> and <see cref="ReleaseHalt"/>.</summary>
    private protected bool IsHalted
    {
        get
        {
            lock (Gate)
            {
                return _halted is not null;
            }
        }
    }

    private Task WhileHaltedAsync(CancellationToken token)
    {
        Task? wait;
        lock (Gate)
        {
            wait = _halted?.Task;
        }
        return wait is null ? Task.CompletedTask : wait.WaitAsync(token);
    }

    /// <summary>Refuses a position that is not a number or further than <see cref="MaxCoordinate"/> on some axis.</summary>
    private static void RequirePlace(Vector p)
    {
        if (!p.IsFinite || Math.Abs(p.X) > MaxCoordinate || Math.Abs(p.Y) > MaxCoordinate || Math.Abs(p.Z) > MaxCoordinate)
        {
            throw new VirtualRefusalException($"the target {p} is not a place a robot can go (coordinates beyond {Num.G(MaxCoordinate)} mm or not numbers).", VirtualRefusalKind.Reach);
        }
    }

    /// <summary>A linear move to a TCP pose: with a model the joints follow (the solution closest to the current ones), or a refusal when unreachable.</summary>
    private protected TState MoveLinear(TState s, Vector position, Rotation rotation)
    {
        RequirePlace(position);
        var next = s with { Position = position, Rotation = rotation };
        if (Model is null)
        {
            return (TState)next;
        }
        var flange = new Pose(position, rotation) * (s.Tool ?? Pose.Identity).Inverse();
        Joints joints = Model.Kinematics.Closest(flange, s.Joints)
            ?? throw new VirtualRefusalException($"the {Model.Name} cannot reach {new Pose(position, rotation)} (outside its reach or joint limits).", VirtualRefusalKind.Reach);
        return (TState)(next with { Joints = joints });
    }

    /// <summary>A joint move: with a model the pose follows (forward kinematics and the tool), or a refusal beyond the joint limits.</summary>
    private protected TState MoveJoints(TState s, Joints joints)
    {
        var next = s with { Joints = joints };
        if (Model is null)
        {
            return (TState)next;
        }
        if (!Model.Kinematics.IsWithinLimits(joints))
        {
            throw new VirtualRefusalException($"the joints {joints} are beyond the limits of the {Model.Name}.", VirtualRefusalKind.JointLimits);
        }
        Pose tcp = Model.Kinematics.Forward(joints) * (s.Tool ?? Pose.Identity);
        return (TState)(next with { Position = tcp.Position, Rotation = tcp.Rotation });
    }

    /// <summary>Attaches (or with null detaches) a tool: with a model the flange stays where it is and the reported TCP moves with the tool.</summary>
    private protected TState WithTool(TState s, Pose? tool)
    {
        var next = s with { Tool = tool };
        if (Model is null)
        {
            return (TState)next;
        }
        Pose tcp = Model.Kinematics.Forward(s.Joints) * (tool ?? Pose.Identity);
        return (TState)(next with { Position = tcp.Position, Rotation = tcp.Rotation });
    }

    /// <summary>A speed to divide by: positive, or a refusal naming what it is for.</summary>
    private protected static double Positive(double speed, string what) =>
        speed > 0 ? speed : throw new VirtualRefusalException($"the {what} is {Num.G(speed)}, so the move would never end.", VirtualRefusalKind.Speed);

    /// <summary>The largest single-joint change between two sets of joints, in degrees.</summary>
    private protected static double LargestJointChange(Joints a, Joints b)
    {
        double largest = 0;
        for (int i = 0; i < Joints.Count; i++)
        {
            largest = Math.Max(largest, Math.Abs(b[i] - a[i]));
        }
        return largest;
    }
}

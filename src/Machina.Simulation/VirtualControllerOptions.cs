namespace Machina.Simulation;

/// <summary>
/// Settings every virtual controller shares: the robot it simulates, where that robot starts, how fast time runs and how
/// much it keeps for inspection. Each brand's options derive from this record and set its own defaults.
/// </summary>
public abstract record VirtualControllerOptions
{
    /// <summary>
    /// The simulated arm: its kinematics keep joints and pose consistent, and a target it cannot reach is refused. Null
    /// keeps joints and pose as separate values (a joint move changes only the joints, a linear move only the pose).
    /// </summary>
    public RobotModel? Model { get; init; }

    /// <summary>Joint angles (degrees) at start.</summary>
    public Joints InitialJoints { get; init; }

    /// <summary>
    /// TCP position (mm) at start, or null for where <see cref="InitialJoints"/> put the flange. With a model, the joints
    /// then start at the solution for this pose closest to <see cref="InitialJoints"/>.
    /// </summary>
    public Vector? InitialPosition { get; init; }

    /// <summary>TCP orientation at start, or null for the orientation <see cref="InitialJoints"/> give (tool down without a model).</summary>
    public Rotation? InitialRotation { get; init; }

    /// <summary>How much faster than real time motions and waits run (10 = ten times faster). Default 1.</summary>
    public double SpeedFactor { get; init; } = 1;

    /// <summary>When true every instruction completes at once (for tests and benchmarks). Default false.</summary>
    public bool InstantExecution { get; init; }

    /// <summary>
    /// Kept for compatibility (at least 1; default 1000): the core no longer queues requests. A twin holds what its driver holds,
    /// as the robot would (the KUKA driver's ring of 100, what reached the ABB driver's socket, one UR instruction).
    /// </summary>
    public int BufferCapacity { get; init; } = 1000;

    /// <summary>How many received requests are kept for inspection (oldest dropped). 0 keeps none. Default 10 000.</summary>
    public int RequestLogCapacity { get; init; } = 10_000;

    /// <summary>Clock used for motion timing and state reports. Default: the system clock.</summary>
    public TimeProvider TimeProvider { get; init; } = TimeProvider.System;

    /// <summary>Faults the controller injects by itself, from a seed (connection drops, delays, garbage, restarts…). Default: none.</summary>
    public VirtualFaults Faults { get; init; } = new();

    /// <summary>
    /// Where a controller whose driver has a monitor channel (ABB, KUKA) listens: this address (default 127.0.0.1), at
    /// <see cref="ListenPort"/> and the next port. The command line's <c>machina sim --bind --port</c> listens here itself rather
    /// than through a relay, whose extra hop cost more processor time per streamed action than the twin's own work (issue 45).
    /// </summary>
    internal System.Net.IPAddress ListenAddress { get; init; } = System.Net.IPAddress.Loopback;

    /// <summary>The driver's port at <see cref="ListenAddress"/> (the monitor's is the next); 0, the default: the system chooses.</summary>
    internal int ListenPort { get; init; }

    /// <summary>
    /// Told of each host that connects to a driver or monitor port and of its leaving, with the port's name ("driver",
    /// "monitor") and the host's address and port; null (the default) tells nobody. Called on the controller's threads.
    /// </summary>
    internal Action<string, string, bool>? ConnectionSeen { get; init; }

    /// <summary>Throws <see cref="ArgumentException"/> naming the first setting that cannot work.</summary>
    internal virtual void Validate()
    {
        if (!(SpeedFactor > 0) || !double.IsFinite(SpeedFactor))
        {
            throw new ArgumentException("SpeedFactor must be a positive number.", nameof(SpeedFactor));
        }
        if (BufferCapacity < 1)
        {
            throw new ArgumentException("BufferCapacity must be at least 1.", nameof(BufferCapacity));
        }
        if (RequestLogCapacity < 0)
        {
            throw new ArgumentException("RequestLogCapacity cannot be negative.", nameof(RequestLogCapacity));
        }
        ArgumentNullException.ThrowIfNull(TimeProvider);
        ArgumentNullException.ThrowIfNull(ListenAddress);
        if (ListenPort is < 0 or >= System.Net.IPEndPoint.MaxPort)
        {
            throw new ArgumentException("ListenPort must be 0 (the system chooses) or a port below 65535 (the monitor takes the next).", nameof(ListenPort));
        }
        ArgumentNullException.ThrowIfNull(Faults);
        Faults.Validate();
        if (InitialPosition is { IsFinite: false } || !InitialJoints.IsFinite)
        {
            throw new ArgumentException("The initial position and joints must be finite numbers.");
        }
    }

    /// <summary>
    /// The starting pose and joints: from the model when there is one (forward kinematics of <see cref="InitialJoints"/>, or
    /// the closest solution for <see cref="InitialPosition"/>), otherwise the given values with <paramref name="fallback"/>.
    /// </summary>
    internal (Vector Position, Rotation Rotation, Joints Joints) StartingPoint(Pose fallback)
    {
        if (Model is null)
        {
            return (InitialPosition ?? fallback.Position, InitialRotation ?? fallback.Rotation, InitialJoints);
        }
        Pose flange = Model.Kinematics.Forward(InitialJoints);
        if (InitialPosition is null && InitialRotation is null)
        {
            return (flange.Position, flange.Rotation, InitialJoints);
        }
        var pose = new Pose(InitialPosition ?? flange.Position, InitialRotation ?? flange.Rotation);
        Joints joints = Model.Kinematics.Closest(pose, InitialJoints)
            ?? throw new ArgumentException($"The {Model.Name} cannot reach the initial pose {pose}; give reachable initial values or no model.");
        return (pose.Position, pose.Rotation, joints);
    }
}

namespace Machina;

/// <summary>
/// The link to the program running on a controller: opens the connection, turns released actions into wire requests and
/// reports acknowledgements, live poses and faults to an <see cref="IDeviceListener"/>.
/// </summary>
internal interface IDeviceDriver : IAsyncDisposable
{
    /// <summary>"host:port" of the controller once connected, else empty.</summary>
    string RemoteAddress { get; }

    /// <summary>Opens the connection and waits for the controller's handshake; throws <see cref="MachinaException"/> on failure.</summary>
    Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken);

    /// <summary>
    /// Queues the frame of a released action (encoded by the brand when it was issued) for sending. Returns true when the
    /// controller will acknowledge the action, false when there is nothing to send (it then counts as executed as soon as
    /// everything released before it is executed). Called on the session's loop: it must not block.
    /// </summary>
    bool Send(RobotAction action, ActionFrame frame);

    /// <summary>
    /// The most actions the controller's driver holds sent and not yet acknowledged (its buffer), or null when it has no
    /// limit of its own. The session never releases more than this, whatever the release window allows.
    /// </summary>
    int? Capacity => null;

    /// <summary>The id the controller knows an action by (the ids of <see cref="DeviceProgress"/>).</summary>
    int WireId(int actionId);

    /// <summary>
    /// Expects the acknowledgement of an action that an earlier connection sent and the controller still holds (it is not
    /// sent again). Called on the session's loop, in release order, before anything new is sent.
    /// </summary>
    void Adopt(int actionId);

    /// <summary>
    /// Asks a controller that stopped on its own (<see cref="IDeviceListener.OnStopped"/>) to run again, e.g. UR: unlock the
    /// protective stop and play. Completes once it runs (the listener then gets <see cref="IDeviceListener.OnResumed"/>);
    /// throws <see cref="MachinaException"/> when it cannot. Drivers that never report stops keep the default.
    /// </summary>
    Task ResumeAsync(CancellationToken cancellationToken) =>
        Task.FromException(new NotSupportedException("This controller does not report stops, so there is nothing to resume."));

    /// <summary>
    /// Holds the program on the controller, out of band: a motion in progress stops on its path, nothing more runs until
    /// <see cref="ResumeAsync"/>, which goes on where it stopped. Completes once the controller holds it.
    /// </summary>
    Task PauseAsync(CancellationToken cancellationToken) =>
        Task.FromException(new NotSupportedException("Pausing is not available for this controller; ClearPendingActions drops what is not sent."));

    /// <summary>
    /// Stops the program on the controller now, out of band: a motion in progress stops where the arm is and nothing after it
    /// runs. Completes once the controller stopped; the program must be started again to go on.
    /// </summary>
    Task StopMotionAsync(CancellationToken cancellationToken) =>
        Task.FromException(new NotSupportedException("Stopping the motion is not available for this controller; ClearPendingActions drops what is not sent."));
}

/// <summary>Receives what a device driver hears from its controller. Calls may come from the driver's receive loops.</summary>
internal interface IDeviceListener
{
    /// <summary>The controller finished the action with this id.</summary>
    void OnAcknowledged(int id);

    /// <summary>The controller finished the read with this id and sent the value it read (a digital input: 1 or 0).</summary>
    void OnAcknowledged(int id, double value) => OnAcknowledged(id);

    /// <summary>The controller reported where the robot is now.</summary>
    void OnMotion(in MotionSample sample);

    /// <summary>
    /// The controller stopped on its own (protective or emergency stop) and the link stays open: nothing more is sent until it
    /// runs again. Actions it holds are neither lost nor sent twice.
    /// </summary>
    void OnStopped(MachinaException reason);

    /// <summary>The controller runs again after <see cref="OnStopped"/> (cleared at its pendant, or by <see cref="IDeviceDriver.ResumeAsync"/>).</summary>
    void OnResumed();

    /// <summary>
    /// The controller could not run the action with this id (its wire id, as in <see cref="OnAcknowledged(int)"/>) and stopped its
    /// program: <paramref name="reason"/> in the controller's words, <paramref name="code"/> its error number or null. Everything
    /// acknowledged before it ran; nothing after it will run.
    /// </summary>
    void OnFailed(int id, string reason, string? code);

    /// <summary>
    /// Like <see cref="OnFailed"/> for a controller that says only how far its stopped program got: the first action in flight
    /// after the one with wire id <paramref name="executedId"/> (0: none ran) could not run. The session, which alone keeps what is in
    /// flight, names it (wire ids grow in release order). UR: RTDE's executed register and its "stopped" state.
    /// </summary>
    void OnFailedAfter(int executedId, string reason, string? code);

    /// <summary>The link failed (closed socket, garbage, protocol violation); the driver stops after this call.</summary>
    void OnFault(MachinaException error);
}

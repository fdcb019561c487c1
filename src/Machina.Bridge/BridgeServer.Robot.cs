namespace Machina.Bridge;

public sealed partial class BridgeServer
{
    private void Subscribe()
    {
        Robot.ActionIssued += OnRobotEvent;
        Robot.ActionReleased += OnRobotEvent;
        Robot.ActionExecuted += OnRobotEvent;
        Robot.ActionFailed += OnActionFailed;
        Robot.MotionUpdate += OnMotionUpdate;
        Robot.ConnectionLost += OnConnectionLost;
    }

    private void Unsubscribe()
    {
        Robot.ActionIssued -= OnRobotEvent;
        Robot.ActionReleased -= OnRobotEvent;
        Robot.ActionExecuted -= OnRobotEvent;
        Robot.ActionFailed -= OnActionFailed;
        Robot.MotionUpdate -= OnMotionUpdate;
        Robot.ConnectionLost -= OnConnectionLost;
    }

    /// <summary>Action events go to every client as the library writes them (one line of JSON in the original's shape).</summary>
    private void OnRobotEvent(object? sender, MachinaEventArgs e)
    {
        Broadcast(e.ToJsonString());
        if (e is ActionExecutedArgs)
        {
            SendArm(e.Axes);
        }
    }

    /// <summary>
    /// To the clients that asked for it (<c>?arm=1</c>): where the arm's joints are for <paramref name="axes"/>, from the robot's
    /// model (<see cref="RobotModel.LinkPositions"/>, as <c>machina preview</c> draws the arm), when it changed. Nothing without a
    /// model or joints.
    /// </summary>
    private void SendArm(Joints? axes)
    {
        if (axes is not Joints joints || Robot.Model is not RobotModel model)
        {
            return;
        }
        string json = BridgeEvents.Arm(model.LinkPositions(joints));
        if (json == _lastArm)
        {
            return;
        }
        _lastArm = json;
        BridgeClient[] clients;
        lock (_gate)
        {
            clients = _clients;
        }
        foreach (BridgeClient client in clients)
        {
            if (client.WantsArm)
            {
                client.Send(json);
            }
        }
    }

    /// <summary>A failed action goes to every client as the <c>action-failed</c> event (with the controller's reason), and to the log.</summary>
    private void OnActionFailed(object? sender, ActionFailedArgs e)
    {
        Robot.Logger.Warning($"Bridge: the controller could not run action #{e.Action.Id} ({e.Action}) and stopped: {e.Reason}");
        Broadcast(e.ToJsonString());
    }

    /// <summary>
    /// Motion updates go to every client only when the reported state changed: a controller reports many times a second even
    /// at rest, and the original sent each of them. Online events are raised one at a time, so no lock is needed here.
    /// </summary>
    private void OnMotionUpdate(object? sender, MotionUpdateArgs e)
    {
        string json = e.ToJsonString();
        if (json != _lastMotion)
        {
            _lastMotion = json;
            Broadcast(json);
            SendArm(e.Axes);
        }
    }

    private void OnConnectionLost(object? sender, ConnectionLostArgs e) =>
        Robot.Logger.Warning("Bridge: the connection to the controller was lost; the next message from a client makes the bridge try to reconnect.");

    /// <summary>Tries once, in the background, to connect the robot again (a message arrived while it was disconnected).</summary>
    private void StartReconnecting()
    {
        lock (_gate)
        {
            if (_state != 1 || _reconnecting is { IsCompleted: false })
            {
                return;
            }
            _reconnecting = Task.Run(ReconnectAsync, CancellationToken.None);
        }
    }

    private async Task ReconnectAsync()
    {
        (string host, int port) = _embedded is { } embedded ? ("127.0.0.1", embedded.Port) : (_options.ControllerHost!, _options.ControllerPort);
        try
        {
            await Robot.ConnectAsync(host, port, _stopping!.Token).ConfigureAwait(false);
            Robot.Logger.Info($"Bridge: reconnected to the controller at {host}:{port}.");
        }
        catch (Exception e) when (e is MachinaException or OperationCanceledException or InvalidOperationException or ObjectDisposedException)
        {
            Robot.Logger.Warning($"Bridge: could not reconnect to the controller at {host}:{port}: {e.Message}");
        }
    }
}

using System.Globalization;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private async Task ExecuteRequestsAsync(CancellationToken token)
    {
        var reader = _buffer.Reader;
        try
        {
            while (await reader.WaitToReadAsync(token).ConfigureAwait(false))
            {
                await WhileStoppedAsync(token).ConfigureAwait(false);
                if (!reader.TryRead(out var request))
                {
                    continue;
                }
                await ExecuteAsync(request, token).ConfigureAwait(false);
                Interlocked.Increment(ref _requestsExecuted);
                // Before the acknowledgement goes out: whoever sees it also sees the pause it may start.
                CountTowardsPause();
                if (request.Code == (int)AbbInstructionCode.GetInfo)
                {
                    await SendToClientAsync(InformationReply(request), token).ConfigureAwait(false);
                }
                // Marked executed under the send lock: a handshake reports as executed exactly the requests whose
                // acknowledgement went to an earlier client (or was lost).
                if (await SendToClientAsync(AbbMessageFormat.Acknowledgement(request.Id, request.Code), token, executedId: request.Id).ConfigureAwait(false))
                {
                    Interlocked.Increment(ref _acknowledgementsSent);
                    CountTowardsClose();
                }
                else
                {
                    Pendant("acknowledgement lost, client disconnected");
                }
                if (request.Code == (int)AbbInstructionCode.StopExecution)
                {
                    // The driver program ends: no more clients.
                    _driverListener?.Stop();
                    DropClient();
                    return;
                }
            }
        }
        catch (OperationCanceledException)
        {
            // Stopping.
        }
    }

    private async Task ExecuteAsync(AbbRequest request, CancellationToken token)
    {
        VirtualAbbState from;
        lock (_gate)
        {
            from = _state;
        }
        var (to, seconds) = Plan(from, request);
        var duration = _options.InstantExecution || seconds <= 0
            ? TimeSpan.Zero
            : TimeSpan.FromSeconds(seconds / _options.SpeedFactor);
        if (duration > TimeSpan.Zero)
        {
            lock (_gate)
            {
                _motion = new VirtualMotion(from, to, _time.GetTimestamp(), duration);
            }
            await Task.Delay(duration, _time, token).ConfigureAwait(false);
        }
        lock (_gate)
        {
            _state = to;
            _motion = null;
        }
    }

    /// <summary>The state after <paramref name="r"/> and how long it takes in real seconds (before the speed factor).</summary>
    private (VirtualAbbState State, double Seconds) Plan(VirtualAbbState s, AbbRequest r)
    {
        double speed = Math.Max(s.Speed, 0.001);
        switch (r.Instruction)
        {
            case AbbInstructionCode.MoveL or AbbInstructionCode.MoveJ:
            {
                var (position, rotation) = Target(r, 0);
                return (WithPose(s, position, rotation), MoveSeconds(Vector.Distance(s.Position, position), s.Rotation.AngleTo(rotation), speed));
            }
            case AbbInstructionCode.MoveC:
            {
                var (position, rotation) = Target(r, 0);
                var through = new Vector(r[7], r[8], r[9]);
                double length = Vector.Distance(s.Position, through) + Vector.Distance(through, position);
                return (WithPose(s, position, rotation), MoveSeconds(length, s.Rotation.AngleTo(rotation), speed));
            }
            case AbbInstructionCode.MoveAbsJ:
            {
                var joints = new Joints(r[0], r[1], r[2], r[3], r[4], r[5]);
                var delta = joints - s.Joints;
                double largest = new[] { delta.J1, delta.J2, delta.J3, delta.J4, delta.J5, delta.J6 }.Max(Math.Abs);
                var next = s with { Joints = joints };
                if (_options.Kinematics is { } model)
                {
                    var (position, rotation) = model.Forward(joints);
                    next = next with { Position = position, Rotation = rotation };
                }
                return (next, largest / speed);
            }
            case AbbInstructionCode.Speed:
                return (s with { Speed = r[0] }, 0);
            case AbbInstructionCode.Zone:
                return (s with { Zone = r[0] }, 0);
            case AbbInstructionCode.WaitTime:
                return (s, Math.Max(0, r[0]));
            case AbbInstructionCode.TPWrite:
                Pendant(r.Text ?? "");
                return (s, 0);
            case AbbInstructionCode.Tool:
                return (s with { ToolTcp = new Vector(r[0], r[1], r[2]), ToolWeight = r[7] == 0 ? 1 : r[7] }, 0);
            case AbbInstructionCode.NoTool:
                return (s with { ToolTcp = null, ToolWeight = null }, 0);
            case AbbInstructionCode.SetDO:
                return (s with { DigitalOutputs = With(s.DigitalOutputs, r.Text ?? "", r[0] != 0) }, 0);
            case AbbInstructionCode.SetAO:
                return (s with { AnalogOutputs = With(s.AnalogOutputs, r.Text ?? "", r[0]) }, 0);
            case AbbInstructionCode.ExternalAxesAll:
                return (s with { ExternalAxesCartesian = Axes(r), ExternalAxesJoints = Axes(r) }, 0);
            case AbbInstructionCode.ExternalAxesRobTarget:
                return (s with { ExternalAxesCartesian = Axes(r) }, 0);
            case AbbInstructionCode.ExternalAxesJointTarget:
                return (s with { ExternalAxesJoints = Axes(r) }, 0);
            case AbbInstructionCode.Acceleration:
                return (s with { AccelerationLimit = r[0] > 0 ? r[0] : null }, 0);
            case AbbInstructionCode.SingularityArea:
                return (s with { WristSingularityArea = r[0] != 0 }, 0);
            case AbbInstructionCode.WorkObject:
                return (s with { WorkObjectOrigin = new Vector(r[0], r[1], r[2]) }, 0);
            case AbbInstructionCode.NoWorkObject:
                return (s with { WorkObjectOrigin = null }, 0);
            case AbbInstructionCode.CustomAction:
                Pendant("Custom action request");
                return (s, 0);
            case AbbInstructionCode.SetMotionUpdateInterval:
                if (r[0] > 0)
                {
                    lock (_gate)
                    {
                        _monitorPeriod = TimeSpan.FromSeconds(Math.Max(r[0], 0.001));
                    }
                }
                return (s, 0);
            case AbbInstructionCode.StopExecution or AbbInstructionCode.GetInfo:
                return (s, 0);
            default:
                Pendant("Don't understand action code " + r.Code.ToString(CultureInfo.InvariantCulture));
                return (s, 0);
        }
    }

    private VirtualAbbState WithPose(VirtualAbbState s, Vector position, Rotation rotation)
    {
        var next = s with { Position = position, Rotation = rotation };
        if (_options.Kinematics?.Inverse(position, rotation, s.Joints) is { } joints)
        {
            next = next with { Joints = joints };
        }
        return next;
    }

    /// <summary>Seconds for a move: the TCP travels at the speed in mm/s and turns at the same number in °/s (the driver copies v_tcp into v_ori).</summary>
    private static double MoveSeconds(double millimetres, double degrees, double speed) => Math.Max(millimetres, degrees) / speed;

    private static (Vector Position, Rotation Rotation) Target(AbbRequest r, int start)
    {
        var position = new Vector(r[start], r[start + 1], r[start + 2]);
        try
        {
            return (position, Rotation.FromQuaternion(r[start + 3], r[start + 4], r[start + 5], r[start + 6]));
        }
        catch (ArgumentException)
        {
            return (position, Rotation.Identity);
        }
    }

    private static ExternalAxes Axes(AbbRequest r) => new(r[0], r[1], r[2], r[3], r[4], r[5]);

    private static Dictionary<string, T> With<T>(IReadOnlyDictionary<string, T> old, string key, T value) =>
        new(old) { [key] = value };

    private string InformationReply(AbbRequest r)
    {
        var v = _options.DriverVersion;
        string payload = r[0] == 2
            ? $"127.0.0.1 {Port.ToString(CultureInfo.InvariantCulture)}"
            : $"{v.Major}.{v.Minor}.{Math.Max(0, v.Build)}";
        return $"$@{r.Id.ToString(CultureInfo.InvariantCulture)} 101 {Num.G(r[0])} {payload};";
    }

    private void Pendant(string text)
    {
        lock (_gate)
        {
            Keep(_pendant, text, MaxKeptTexts);
        }
    }
}

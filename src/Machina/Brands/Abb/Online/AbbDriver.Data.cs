namespace Machina;

internal sealed partial class AbbDriver
{
    /// <summary>Handles a data message: the four handshake parts, or a live pose.</summary>
    private void OnData(in AbbMessage message)
    {
        switch ((AbbResponseCode)message.Code)
        {
            case AbbResponseCode.Version:
                _version = message.ToVersion();
                break;
            case AbbResponseCode.Pose:
                AbbPose pose = message.ToPose();
                _position = pose.Position;
                _rotation = pose.Rotation;
                break;
            case AbbResponseCode.Joints:
                _axes = message.ToJoints();
                break;
            case AbbResponseCode.ExternalAxes:
                ExternalAxes axes = message.ToExternalAxes();
                _externalAxes = axes.IsEmpty ? null : axes;
                _hasExternalAxes = true;
                break;
            case AbbResponseCode.Progress:
                _progress = message.ToProgress();
                break;
            case AbbResponseCode.FullPose:
                _listener?.OnMotion(Sample(message.ToMonitorUpdate()));
                return;
            default:
                _log.Debug($"Ignored data message from the controller: {message}");
                return;
        }
        if (!_handshake.Task.IsCompleted && _version is AbbDriverVersion version && _position is not null && _axes is not null && _hasExternalAxes
            && (_progress is not null || !version.ReportsProgress))
        {
            _handshake.TrySetResult(new DeviceHandshake(version.ToString(), _position, _rotation, _axes, _externalAxes, _progress));
        }
    }

    private static MotionSample Sample(AbbMonitorUpdate update) =>
        new(update.Position, update.Rotation, update.Joints, update.ExternalAxes.IsEmpty ? null : update.ExternalAxes);

    /// <summary>Reads the monitor connection: live poses (<c>$24</c>). A failing monitor is logged; it never stops streaming.</summary>
    private sealed class MonitorReceiver(AbbDriver driver) : ILinkReceiver
    {
        private readonly AbbMessageReader _reader = new();
        private bool _stopped;

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (_stopped)
            {
                return;
            }
            _reader.Append(data);
            try
            {
                while (!_stopped && Volatile.Read(ref driver._failed) == 0 && _reader.TryRead(out AbbMessage message))
                {
                    if (message.Kind == AbbMessageKind.Data && message.Code == (int)AbbResponseCode.FullPose)
                    {
                        driver._listener?.OnMotion(Sample(message.ToMonitorUpdate()));
                    }
                    else
                    {
                        Stop($"it sent \"{message}\"");
                    }
                }
            }
            catch (AbbProtocolException ex)
            {
                Stop(ex.Message);
            }
        }

        public void OnClosed(Exception? error) => Stop(error is null ? "the controller closed the monitor connection" : error.Message);

        private void Stop(string why)
        {
            if (!_stopped && Volatile.Read(ref driver._failed) == 0)
            {
                _stopped = true;
                driver._log.Warning($"Motion updates stopped: {why}.");
            }
        }
    }
}

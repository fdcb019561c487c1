namespace Machina;

internal sealed partial class AbbDriver
{
    private bool OnData(int code, ReadOnlySpan<double> v, ReadOnlySpan<byte> message)
    {
        switch ((AbbResponseCode)code)
        {
            case AbbResponseCode.Version when v.Length == 3:
                _version = $"{Num.G(v[0])}.{Num.G(v[1])}.{Num.G(v[2])}";
                break;
            case AbbResponseCode.Pose when v.Length == 7:
                _position = new Vector(v[0], v[1], v[2]);
                _rotation = Rotation.FromQuaternion(v[3], v[4], v[5], v[6]);
                break;
            case AbbResponseCode.Joints when v.Length == 6:
                _axes = new Joints(v[0], v[1], v[2], v[3], v[4], v[5]);
                break;
            case AbbResponseCode.ExternalAxes when v.Length == 6:
                _externalAxes = AbbDriverMessage.Axes(v);
                _hasExternalAxes = true;
                break;
            case AbbResponseCode.FullPose when v.Length == 19:
                _listener?.OnMotion(FullPose(v));
                return true;
            case AbbResponseCode.Version or AbbResponseCode.Pose or AbbResponseCode.Joints or AbbResponseCode.ExternalAxes or AbbResponseCode.FullPose:
                return Garbage(message);
            default:
                _log.Debug($"Ignored data message from the controller: {AbbDriverMessage.Text(message)}");
                return true;
        }
        if (!_handshake.Task.IsCompleted && _version is not null && _position is not null && _axes is not null && _hasExternalAxes)
        {
            _handshake.TrySetResult(new DeviceHandshake(_version, _position, _rotation, _axes, _externalAxes));
        }
        return true;
    }

    private static MotionSample FullPose(ReadOnlySpan<double> v) => new(
        new Vector(v[0], v[1], v[2]),
        Rotation.FromQuaternion(v[3], v[4], v[5], v[6]),
        new Joints(v[7], v[8], v[9], v[10], v[11], v[12]),
        AbbDriverMessage.Axes(v[13..]));

    /// <summary>Reads the monitor connection: live poses (<c>$24</c>). A failing monitor is logged; it never stops streaming.</summary>
    private sealed class MonitorReceiver(AbbDriver driver) : ILinkReceiver
    {
        private readonly AbbDriverFraming _framing = new();
        private readonly double[] _values = new double[AbbDriverMessage.MaxValues];
        private bool _stopped;

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (!_stopped && !_framing.Feed(data, this, static (self, message) => self.OnMessage(message)))
            {
                Stop("a message longer than the protocol allows");
            }
        }

        public void OnClosed(Exception? error) => Stop(error is null ? "the controller closed it" : error.Message);

        private bool OnMessage(ReadOnlySpan<byte> message)
        {
            if (_stopped || Volatile.Read(ref driver._failed) != 0)
            {
                return false;
            }
            if (message[0] == (byte)'$' &&
                AbbDriverMessage.TryReadData(message, out int code, _values, out int count) &&
                code == (int)AbbResponseCode.FullPose && count == 19)
            {
                driver._listener?.OnMotion(FullPose(_values.AsSpan(0, 19)));
                return true;
            }
            Stop($"it sent \"{AbbDriverMessage.Text(message)}\"");
            return false;
        }

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

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
            case AbbResponseCode.Failure:
                OnFailure(message);
                return;
            case AbbResponseCode.InputRead when message.Values.Length == 2:
                _read = ((int)message.Values[0], message.Values[1]);
                return;
            case AbbResponseCode.FullPose:
                Listener?.OnMotion(Sample(message.ToMonitorUpdate()));
                return;
            default:
                Log.Debug($"Ignored data message from the controller: {message}");
                return;
        }
        if (!IsHandshakeOver && _version is AbbDriverVersion version && _position is not null && _axes is not null && _hasExternalAxes
            && (_progress is not null || !version.ReportsProgress))
        {
            Handshake(new DeviceHandshake(version.ToString(), _position, _rotation, _axes, _externalAxes, _progress));
        }
    }

    /// <summary>A <c>$26 id code;</c> report: the action with that wire id failed and the driver stopped.</summary>
    private void OnFailure(in AbbMessage message)
    {
        var (wireId, code) = message.ToFailure();
        Log.Error($"The controller could not run action {wireId}: {AbbFailure.Describe(code)}");
        Listener?.OnFailed(wireId, AbbFailure.Describe(code), code.ToString(System.Globalization.CultureInfo.InvariantCulture));
    }

    private static MotionSample Sample(AbbMonitorUpdate update) =>
        new(update.Position, update.Rotation, update.Joints, update.ExternalAxes.IsEmpty ? null : update.ExternalAxes);

    /// <inheritdoc/>
    /// <remarks>A failure report (<c>$26</c>, from the monitor task's error trap) is handled here too; the monitor stops after it.</remarks>
    protected override bool TryReadMotion(in AbbMessage message, out MotionSample sample)
    {
        if (message.Kind == AbbMessageKind.Data && message.Code == (int)AbbResponseCode.Failure)
        {
            OnFailure(message);
            sample = default;
            return false;
        }
        bool isPose = message.Kind == AbbMessageKind.Data && message.Code == (int)AbbResponseCode.FullPose;
        sample = isPose ? Sample(message.ToMonitorUpdate()) : default;
        return isPose;
    }

    /// <inheritdoc/>
    /// <remarks>The monitor task's answer to an out-of-band command (<c>$28 n;</c>, see <see cref="PauseAsync"/>).</remarks>
    protected override bool TryHandleMonitorMessage(in AbbMessage message)
    {
        if (message.Kind == AbbMessageKind.Data && message.Code == (int)AbbResponseCode.Control && message.Values.Length == 1)
        {
            OnControl((int)message.Values[0]);
            return true;
        }
        if (message.Kind == AbbMessageKind.Information && message.Code == (int)AbbInstructionCode.GetInfo)
        {
            OnInformation(message);
            return true;
        }
        return false;
    }

    /// <inheritdoc/>
    protected override string Describe(in AbbMessage message) => $"\"{message}\"";
}

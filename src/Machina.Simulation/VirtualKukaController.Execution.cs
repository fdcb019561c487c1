using System.Globalization;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>The driver's <c>$VEL_AXIS</c> for joint (PTP) motions: this share of each axis's top speed.</summary>
    internal const double AxisSpeedShare = 0.2;

    /// <summary>How fast the tool turns during a linear motion, degrees per second (<c>$VEL.ORI1</c>).</summary>
    internal const double OrientationSpeed = 200;

    private byte[]? _heldAcknowledgement;

    private protected override async Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token)
    {
        if (request is TwinAction twinAction)
        {
            // Planned means acknowledged by the driver already.
            return await AcknowledgeTwinAsync(await twinAction.Acknowledged.Task.ConfigureAwait(false), token).ConfigureAwait(false);
        }
        byte[] ack = Encoding.ASCII.GetBytes(KukaMessages.Acknowledgement(id));
        switch (_options.AcknowledgementWrites)
        {
            case AcknowledgementWrites.Split:
                // The first part records the action as executed; the rest completes the element.
                await SendToClientAsync(ack.AsMemory(0, 4), token, executedId: id).ConfigureAwait(false);
                await AcknowledgeAsync(ack.AsMemory(4), id, token).ConfigureAwait(false);
                break;
            case AcknowledgementWrites.Joined when _heldAcknowledgement is null && BufferedRequestCount > 0:
                // Held until the next action is done; until then this one counts as received, not executed.
                _heldAcknowledgement = ack;
                break;
            case AcknowledgementWrites.Joined when _heldAcknowledgement is not null:
                await AcknowledgeAsync(_heldAcknowledgement.Concat(ack).ToArray(), id, token).ConfigureAwait(false);
                _heldAcknowledgement = null;
                break;
            default:
                await AcknowledgeAsync(ack, id, token).ConfigureAwait(false);
                break;
        }
        return true;
    }

    /// <summary>The state after <paramref name="request"/> and how long it takes in real seconds (before the speed factor).</summary>
    private protected override VirtualStep Plan(VirtualKukaState s, object request)
    {
        if (request is TwinAction twinAction)
        {
            AwaitTwinAction(twinAction, _twinToken);
            // The twin's driver ran it on its arm already: the state the controller keeps is the twin's now.
            return new(Twin is { } twin ? TwinState(twin, s) : s, 0);
        }
        var a = (KukaInstruction)request;
        KukaValues v = a.Values;
        switch (a.Code)
        {
            case KukaActionCode.Linear:
            {
                var (position, rotation) = Frame(v);
                double seconds = Math.Max(Vector.Distance(s.Position, position) / Positive(s.Speed, "speed ($VEL.CP)"), s.Rotation.AngleTo(rotation) / OrientationSpeed);
                return new(MoveLinear(s, position, rotation), seconds);
            }
            case KukaActionCode.JointToPose:
            {
                var (position, rotation) = Frame(v);
                VirtualKukaState next = MoveLinear(s, position, rotation);
                return new(next, JointSeconds(s.Joints, next.Joints, s.Speed), InJointSpace: true);
            }
            case KukaActionCode.JointToAxes:
            {
                var joints = new Joints(v[0], v[1], v[2], v[3], v[4], v[5]);
                return new(MoveJoints(s, joints), JointSeconds(s.Joints, joints, s.Speed), InJointSpace: true);
            }
            case KukaActionCode.Speed:
                return new(s with { Speed = Positive(v[0], "speed ($VEL.CP)") * 1000 }, 0);
            case KukaActionCode.Acceleration:
                return new(s with { Acceleration = v[0] > 0 ? v[0] : null }, 0);
            case KukaActionCode.Precision:
                return new(s with { Zone = v[0] }, 0);
            case KukaActionCode.Wait:
                return new(s, Math.Max(0, v[0]));
            case KukaActionCode.Message:
                Pendant(a.Text);
                return new(s, 0);
            case KukaActionCode.AttachTool:
            {
                var (position, rotation) = Frame(v);
                return new(WithTool(s, new Pose(position, rotation)), 0);
            }
            case KukaActionCode.DetachTool:
                return new(WithTool(s, null), 0);
            case KukaActionCode.DigitalOutput:
                return new(s with { DigitalOutputs = With(s.DigitalOutputs, Output(v[0], KukaActionEncoder.DigitalOutputs), v[1] > 0.5) }, 0);
            case KukaActionCode.AnalogOutput:
                return new(s with { AnalogOutputs = With(s.AnalogOutputs, Output(v[0], KukaActionEncoder.AnalogOutputs), AnalogValue(v[1])) }, 0);
            case KukaActionCode.Settings:
                return new(s with { Speed = Positive(v[0], "speed ($VEL.CP)") * 1000, Acceleration = v[1] > 0 ? v[1] : null, Zone = v[2] }, 0);
            default:
                throw new VirtualRefusalException($"action type {((int)a.Code).ToString(CultureInfo.InvariantCulture)} is not one the driver knows.");
        }
    }

    /// <summary>
    /// Seconds of a joint motion: every axis arrives together, the slowest at <see cref="AxisSpeedShare"/> of its top speed;
    /// without a model (or its speeds) the largest change runs at the TCP speed's number in degrees per second.
    /// </summary>
    private double JointSeconds(Joints from, Joints to, double speed)
    {
        if (Model?.MaxJointSpeeds is not Joints top)
        {
            return LargestJointChange(from, to) / Positive(speed, "speed");
        }
        double seconds = 0;
        for (int i = 0; i < Joints.Count; i++)
        {
            seconds = Math.Max(seconds, Math.Abs(to[i] - from[i]) / (top[i] * AxisSpeedShare));
        }
        return seconds;
    }

    private static (Vector Position, Rotation Rotation) Frame(KukaValues v) => (new Vector(v[0], v[1], v[2]), KrlFormat.FromAbc(v[3], v[4], v[5]));

    /// <summary>The number of an output, or a refusal when it does not exist.</summary>
    private static string Output(double number, int count) => number == Math.Floor(number) && number >= 1 && number <= count
        ? ((int)number).ToString(CultureInfo.InvariantCulture)
        : throw new VirtualRefusalException($"output {Num.G(number)} does not exist (1 to {count.ToString(CultureInfo.InvariantCulture)}).", VirtualRefusalKind.Output);

    /// <summary>$ANOUT takes -1 to 1; the driver checks it before setting the output.</summary>
    private static double AnalogValue(double value) => value is >= -1 and <= 1
        ? value
        : throw new VirtualRefusalException($"analog value {Num.G(value)} is outside -1 to 1.", VirtualRefusalKind.OutputValue);

    private static Dictionary<string, T> With<T>(IReadOnlyDictionary<string, T> old, string key, T value) => new(old) { [key] = value };
}

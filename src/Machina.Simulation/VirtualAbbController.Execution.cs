using System.Globalization;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    private protected override async Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token)
    {
        if (request is TwinRequest twin)
        {
            return await AcknowledgeTwinAsync(twin, token).ConfigureAwait(false);
        }
        var r = (AbbRequest)request;
        if (r.Code == (int)AbbInstructionCode.GetInfo)
        {
            await SendToClientAsync(Encoding.ASCII.GetBytes(InformationReply(r)), token).ConfigureAwait(false);
        }
        await AcknowledgeAsync(Encoding.ASCII.GetBytes(AbbMessageFormat.Acknowledgement(r.Id, r.Code)), r.Id, token).ConfigureAwait(false);
        if (r.Code == (int)AbbInstructionCode.StopExecution)
        {
            // The driver program ends: no more clients.
            _driverListener?.Stop();
            DropClient();
            return false;
        }
        return true;
    }

    /// <summary>The state after <paramref name="request"/> and how long it takes in real seconds (before the speed factor).</summary>
    private protected override VirtualStep Plan(VirtualAbbState s, object request)
    {
        if (Twin is { } twin)
        {
            return new(TwinState(twin, s), 0); // the twin's arm already ran it: the acknowledgement reports where it is
        }
        var r = (AbbRequest)request;
        switch (r.Instruction)
        {
            case AbbInstructionCode.MoveL or AbbInstructionCode.MoveJ:
            {
                var (position, rotation) = Target(r, 0);
                return new(MoveLinear(s, position, rotation), MoveSeconds(Vector.Distance(s.Position, position), s.Rotation.AngleTo(rotation), s.Speed));
            }
            case AbbInstructionCode.MoveC:
            {
                var (position, rotation) = Target(r, 0);
                var through = new Vector(r[7], r[8], r[9]);
                double length = Vector.Distance(s.Position, through) + Vector.Distance(through, position);
                return new(MoveLinear(s, position, rotation), MoveSeconds(length, s.Rotation.AngleTo(rotation), s.Speed));
            }
            case AbbInstructionCode.MoveAbsJ:
            {
                var joints = new Joints(r[0], r[1], r[2], r[3], r[4], r[5]);
                return new(MoveJoints(s, joints), LargestJointChange(s.Joints, joints) / Positive(s.Speed, "speed"), InJointSpace: true);
            }
            case AbbInstructionCode.Speed:
                return new(s with { Speed = r[0] }, 0);
            case AbbInstructionCode.Zone:
                return new(s with { Zone = r[0] }, 0);
            case AbbInstructionCode.WaitTime:
                return new(s, Math.Max(0, r[0]));
            case AbbInstructionCode.TPWrite:
                Pendant(r.Text ?? "");
                return new(s, 0);
            case AbbInstructionCode.Tool:
                var tool = WithTool(s, new Pose(new Vector(r[0], r[1], r[2]), Quaternion(r, 3)));
                return new(tool with { ToolWeight = r[7] == 0 ? 1 : r[7] }, 0);
            case AbbInstructionCode.NoTool:
                return new(WithTool(s, null) with { ToolWeight = null }, 0);
            case AbbInstructionCode.SetDO:
                return new(s with { DigitalOutputs = With(s.DigitalOutputs, r.Text ?? "", r[0] != 0) }, 0);
            case AbbInstructionCode.SetAO:
                return new(s with { AnalogOutputs = With(s.AnalogOutputs, r.Text ?? "", r[0]) }, 0);
            case AbbInstructionCode.ExternalAxesAll:
                return new(s with { ExternalAxesCartesian = Axes(r), ExternalAxesJoints = Axes(r) }, 0);
            case AbbInstructionCode.ExternalAxesRobTarget:
                return new(s with { ExternalAxesCartesian = Axes(r) }, 0);
            case AbbInstructionCode.ExternalAxesJointTarget:
                return new(s with { ExternalAxesJoints = Axes(r) }, 0);
            case AbbInstructionCode.Acceleration:
                return new(s with { AccelerationLimit = r[0] > 0 ? r[0] : null }, 0);
            case AbbInstructionCode.SingularityArea:
                return new(s with { WristSingularityArea = r[0] != 0 }, 0);
            case AbbInstructionCode.WorkObject:
                return new(s with { WorkObjectOrigin = new Vector(r[0], r[1], r[2]) }, 0);
            case AbbInstructionCode.NoWorkObject:
                return new(s with { WorkObjectOrigin = null }, 0);
            case AbbInstructionCode.CustomAction:
                Pendant("Custom action request");
                return new(s, 0);
            case AbbInstructionCode.SetMotionUpdateInterval:
                if (r[0] > 0)
                {
                    lock (Gate)
                    {
                        _monitorPeriod = TimeSpan.FromSeconds(Math.Clamp(r[0], 0.001, 3600));
                    }
                }
                return new(s, 0);
            case AbbInstructionCode.StopExecution or AbbInstructionCode.GetInfo:
                return new(s, 0);
            default:
                Pendant("Don't understand action code " + r.Code.ToString(CultureInfo.InvariantCulture));
                return new(s, 0);
        }
    }

    /// <summary>The robot as the RAPID twin's arm has it now (the options' starting state until the twin is made).</summary>
    private protected override VirtualAbbState Observe(VirtualAbbState kept) => Twin is { } twin ? TwinState(twin, kept) : kept;

    /// <summary>Seconds for a move: the TCP travels at the speed in mm/s and turns at the same number in °/s (the driver copies v_tcp into v_ori).</summary>
    private static double MoveSeconds(double millimetres, double degrees, double speed) => Math.Max(millimetres, degrees) / Positive(speed, "speed");

    private static (Vector Position, Rotation Rotation) Target(AbbRequest r, int start) =>
        (new Vector(r[start], r[start + 1], r[start + 2]), Quaternion(r, start + 3));

    private static Rotation Quaternion(AbbRequest r, int start)
    {
        try
        {
            return Rotation.FromQuaternion(r[start], r[start + 1], r[start + 2], r[start + 3]);
        }
        catch (ArgumentException)
        {
            return Rotation.Identity;
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
}

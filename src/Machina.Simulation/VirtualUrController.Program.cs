using System.Buffers.Binary;
using System.Net.Sockets;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>runtime_state values (RTDE guide).</summary>
    internal const uint Stopped = 1, Playing = 2, Paused = 4;

    /// <summary>safety_status values (RTDE guide).</summary>
    internal const int Normal = 1, ProtectiveStopped = 3, RobotEmergencyStopped = 7;

    private int _program;
    private int _instanceRegister;
    private string? _runtimeException;
    private DriverKind _kind;
    private uint _runtime = Stopped;
    private int _safety = Normal;

    /// <summary>True while a driver program runs (playing or paused).</summary>
    public bool IsProgramRunning
    {
        get
        {
            if (Twin is { } twin)
            {
                return twin.State == UrScript.UrProgramState.Running;
            }
            lock (Gate)
            {
                return _runtime != Stopped;
            }
        }
    }

    /// <summary>RTDE runtime_state now: 1 stopped, 2 playing, 4 paused.</summary>
    public uint RuntimeState
    {
        get
        {
            if (Twin is { } twin)
            {
                return TwinRuntime(twin);
            }
            lock (Gate)
            {
                return _runtime;
            }
        }
    }

    /// <summary>RTDE safety_status now: 1 normal, 3 protective stop, 7 robot emergency stop.</summary>
    public int SafetyStatus
    {
        get
        {
            lock (Gate)
            {
                return _safety;
            }
        }
    }

    /// <summary>
    /// Fault injection: a protective stop, as when the robot hits something. The motion stops where the robot is, the program
    /// pauses and nothing more runs until the stop is unlocked and the program played (dashboard, as <c>Robot.Resume</c> does).
    /// False when the robot is already stopped.
    /// </summary>
    public bool ProtectiveStop() => SafetyStop(ProtectiveStopped, "Protective stop");

    /// <summary>Fault injection: the emergency stop button. Like <see cref="ProtectiveStop"/>, but only <see cref="ReleaseEmergencyStop"/> clears it.</summary>
    public bool EmergencyStop() => SafetyStop(RobotEmergencyStopped, "Emergency stop");

    /// <summary>Releases the emergency stop button: the robot is normal again, the program stays paused until played.</summary>
    public void ReleaseEmergencyStop()
    {
        lock (Gate)
        {
            if (_safety == RobotEmergencyStopped)
            {
                _safety = Normal;
            }
        }
        WakeRtde();
    }

    private bool SafetyStop(int status, string text)
    {
        lock (Gate)
        {
            if (_safety != Normal)
            {
                return false;
            }
            _safety = status;

            if (_runtime == Playing)
            {
                _runtime = Paused;
            }
        }
        if (Twin is { } twin)
        {
            twin.Hold(); // the motion stops where the arm is; the program waits until it is played again
        }
        else
        {
            Halt();
        }
        Pendant(text);
        WakeRtde();
        return true;
    }

    /// <summary>Dashboard "unlock protective stop".</summary>
    private string UnlockProtectiveStop()
    {
        lock (Gate)
        {
            if (_safety == RobotEmergencyStopped)
            {
                return "Cannot unlock protective stop: the robot is in an emergency stop";
            }
            _safety = Normal;
        }
        WakeRtde();
        return "Protective stop releasing";
    }

    /// <summary>Dashboard "play": runs the paused program again.</summary>
    private string Play()
    {
        lock (Gate)
        {
            if (_safety != Normal || _kind == DriverKind.None)
            {
                return "Failed to execute: play";
            }
            _runtime = Playing;
        }
        ReleaseHalt();
        WakeRtde();
        return "Starting program";
    }

    /// <summary>Dashboard "pause".</summary>
    private string Pause()
    {
        lock (Gate)
        {
            if (_runtime != Playing)
            {
                return "Failed to execute: pause";
            }
            _runtime = Paused;
        }
        Halt();
        WakeRtde();
        return "Pausing program";
    }

    /// <summary>
    /// The instance number in output_int_register_26: written by each of our driver programs when it starts, kept after it
    /// stops (registers keep their values), 0 until the first.
    /// </summary>
    public int InstanceRegister
    {
        get
        {
            if (Twin is { } twin)
            {
                return (int)twin.Io.GetNumber(UrScript.UrIoBanks.OutputIntRegisters, InstanceRegisterNumber);
            }
            lock (Gate)
            {
                return _instanceRegister;
            }
        }
    }

    /// <summary>The text of the runtime error that stopped the last program (what the pendant and the script ports show after its line), or null.</summary>
    public string? LastRuntimeException
    {
        get
        {
            lock (Gate)
            {
                return _runtimeException;
            }
        }
    }

    /// <summary>
    /// Starts a driver program. Ours publishes its <paramref name="instance"/> first; the progress registers keep what the
    /// programs before it wrote (a program does not reset them).
    /// </summary>
    private int StartProgram(DriverKind kind, int instance)
    {
        int program;
        lock (Gate)
        {
            program = ++_program;
            _kind = kind;
            _runtime = _safety == Normal ? Playing : Paused;
            if (kind == DriverKind.Ours)
            {
                _instanceRegister = instance;
            }
        }
        WakeRtde();
        if (SafetyStatus == Normal)
        {
            ReleaseHalt();
        }
        return program;
    }

    /// <summary>
    /// Ends the running program, if any: the motion in progress stops where the robot is (it is not completed, nor logged as
    /// executed), its connection closes and what it still held is dropped.
    /// </summary>
    private void StopProgram(string why)
    {
        bool wasRunning;
        lock (Gate)
        {
            wasRunning = _kind != DriverKind.None;
            _program++;
            _kind = DriverKind.None;
            _runtime = Stopped;
        }
        Halt(); // released when the next program starts
        DropClient();
        if (wasRunning)
        {
            Pendant("Program stopped: " + why);
            WakeRtde();
        }
    }

    /// <summary>Reads instructions from a driver program's connection into the buffer until it closes or the program is replaced.</summary>
    private async Task ReadProgramAsync(TcpClient client, DriverKind kind, int program, CancellationToken token)
    {
        var reader = new UrRequestReader(client.GetStream(), kind, program);
        try
        {
            while (CurrentProgram == program)
            {
                if (await reader.ReadAsync(token).ConfigureAwait(false) is not UrRequest request)
                {
                    if (reader.EndedInside is (int id, int code))
                    {
                        RecordError($"the connection ended inside instruction {id} (code {code}).");
                    }
                    break;
                }
                if (request.Halts)
                {
                    // Our driver halts there, after running what came before: the stop waits its turn in the buffer.
                    await EnqueueAsync(request, 0, $"{request.Id} {request.Code}", token).ConfigureAwait(false);
                    return;
                }
                await EnqueueAsync(request, Math.Max(request.Id, 0), request.ToString(), token).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException or System.Threading.Channels.ChannelClosedException)
        {
            // Host gone or controller stopping: like the driver, the program runs what it holds.
        }
        DropClient(client);
    }

    private int CurrentProgram
    {
        get
        {
            lock (Gate)
            {
                return _program;
            }
        }
    }

    /// <summary>How many integers follow the header of an instruction; -1 when our driver does not know the code (the original reads none).</summary>
    internal static int ParameterCount(int code, DriverKind kind) => code switch
    {
        1 or 2 or 3 or 17 => 6,
        4 or 5 or 6 or 7 or 8 or 9 or 15 or 16 => 1,
        12 => 7,
        13 => 3,
        14 => kind == DriverKind.Original ? 3 : 2, // the original script reads three, one more than its host sends (bug)
        _ => kind == DriverKind.Original ? 0 : -1,
    };

    private protected override async Task<bool> AfterExecutedAsync(object request, int id, CancellationToken token)
    {
        if (request is TwinAck ack)
        {
            return await AcknowledgeTwinAsync(ack, token).ConfigureAwait(false);
        }
        var r = (UrRequest)request;
        if (r.Program != CurrentProgram)
        {
            return true; // its program was replaced: nobody listens for it
        }
        if (r.Halts)
        {
            RecordError($"unknown instruction code {r.Code} (id {r.Id}): the driver cannot read on, its program stops.");
            StopProgram("unknown instruction");
            return true;
        }
        await AcknowledgeAsync(AcknowledgementBytes(r.Id), Math.Max(r.Id, 0), token).ConfigureAwait(false);
        return true;
    }

    /// <summary>
    /// A request the robot cannot run (an unreachable target, a joint beyond its limits, a speed of 0) stops the program with
    /// a runtime error, as on a UR: the pendant shows it, the script ports send it as a runtime exception message, RTDE
    /// reports runtime_state stopped, the driver connection closes, and the request is never acknowledged.
    /// </summary>
    private protected override bool FailsProgram(object request, string reason)
    {
        if (request is not UrRequest r)
        {
            return false;
        }
        if (r.Program != CurrentProgram || r.Halts)
        {
            return false;
        }
        string function = r.Code switch { 1 => "movel", 2 or 3 => "movej", 17 => "movep", 9 => "sleep", 12 => "set_tcp", _ => "machina_ur_driver" };
        string text = $"{function}: {reason}";
        int line;
        lock (Gate)
        {
            _runtimeException = text;
            line = LineOf(_scripts.Count == 0 ? "" : _scripts[^1], function + "(");
        }
        Pendant($"Runtime error (line {line.ToString(Num.Inv)}): {text}");
        SendRuntimeException(line, text);
        StopProgram("runtime error");
        return true;
    }

    /// <summary>The 1-based number of the first line of <paramref name="script"/> that contains <paramref name="call"/>, or 0.</summary>
    private static int LineOf(string script, string call)
    {
        string[] lines = script.Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            if (lines[i].Contains(call, StringComparison.Ordinal) && !lines[i].TrimStart().StartsWith('#'))
            {
                return i + 1;
            }
        }
        return 0;
    }

    private protected override bool IsStale(object request) => request is UrRequest r && (r.Program != CurrentProgram || r.Halts);

    private protected override byte[] AcknowledgementBytes(int id)
    {
        var bytes = new byte[4];
        BinaryPrimitives.WriteInt32BigEndian(bytes, id);
        return bytes;
    }

    /// <summary>A response (a code below -1) that never ends: more values than any response of the protocol carries.</summary>
    private protected override byte[] GarbageBytes(Random random)
    {
        var values = new int[80];
        values[0] = -100 - random.Next(1000);
        for (int i = 1; i < values.Length; i++)
        {
            values[i] = random.Next(0, int.MaxValue);
        }
        var bytes = new byte[values.Length * 4];
        UrWire.Write(values, bytes);
        return bytes;
    }

    private protected override bool InjectProtectiveStop() => ProtectiveStop();

    private protected override VirtualStep Plan(VirtualUrState s, object request)
    {
        if (Twin is { } twin)
        {
            return new(TwinState(twin, s), 0); // the twin's arm already ran it: the acknowledgement reports where it is
        }
        var r = (UrRequest)request;
        if (r.Program != CurrentProgram || r.Halts)
        {
            return new(s, 0);
        }
        int[] v = r.Values;
        switch (r.Code)
        {
            case 1 or 17:
            {
                var (position, rotation) = PoseOf(v);
                var next = MoveLinear(s, position, rotation);
                double seconds = Math.Max(Vector.Distance(s.Position, position) / Positive(s.Speed, "TCP speed"), s.Rotation.AngleTo(rotation) / Positive(s.JointSpeed, "joint speed"));
                return new(next, seconds);
            }
            case 2:
            {
                var (position, rotation) = PoseOf(v);
                var next = MoveLinear(s, position, rotation);
                double seconds = Model is null
                    ? Vector.Distance(s.Position, position) / Positive(s.Speed, "TCP speed")
                    : LargestJointChange(s.Joints, next.Joints) / Positive(s.JointSpeed, "joint speed");
                return new(next, seconds, InJointSpace: Model is not null);
            }
            case 3:
            {
                var joints = new Joints(UrWire.ToDegrees(v[0]), UrWire.ToDegrees(v[1]), UrWire.ToDegrees(v[2]), UrWire.ToDegrees(v[3]), UrWire.ToDegrees(v[4]), UrWire.ToDegrees(v[5]));
                return new(MoveJoints(s, joints), LargestJointChange(s.Joints, joints) / Positive(s.JointSpeed, "joint speed"), InJointSpace: true);
            }
            case 4:
                return new(s with { Speed = UrWire.ToMillimetres(v[0]) }, 0);
            case 5:
                return new(s with { Acceleration = UrWire.ToMillimetres(v[0]) }, 0);
            case 6:
                return new(s with { JointSpeed = UrWire.ToDegrees(v[0]) }, 0);
            case 7:
                return new(s with { JointAcceleration = UrWire.ToDegrees(v[0]) }, 0);
            case 8:
                return new(s with { Zone = UrWire.ToMillimetres(v[0]) }, 0);
            case 9:
                return new(s, Math.Max(0, v[0]) / UrWire.FactorSecond);
            case 12:
            {
                var (position, rotation) = PoseOf(v);
                var tool = position == Vector.Zero && rotation.IsSimilar(Rotation.Identity, 1e-9) ? (Pose?)null : new Pose(position, rotation);
                return new(WithTool(s, tool) with { Payload = v[6] / UrWire.FactorKilogram }, 0);
            }
            case 13:
            {
                string pin = (v[2] != 0 ? "tool " : "") + v[0].ToString(Num.Inv);
                return new(s with { DigitalOutputs = new Dictionary<string, bool>(s.DigitalOutputs) { [pin] = v[1] != 0 } }, 0);
            }
            case 14:
                return new(s with { AnalogOutputs = new Dictionary<string, double>(s.AnalogOutputs) { [v[0].ToString(Num.Inv)] = v[1] / UrWire.FactorAnalog } }, 0);
            case 15:
            {
                double mm = UrWire.ToMillimetres(v[0]);
                return new(s with { Speed = mm, JointSpeed = mm }, 0);
            }
            case 16:
            {
                double mm = UrWire.ToMillimetres(v[0]);
                return new(s with { Acceleration = mm, JointAcceleration = mm }, 0);
            }
            default:
                Pendant("Unknown instruction code " + r.Code.ToString(Num.Inv));
                return new(s, 0);
        }
    }

    private static (Vector Position, Rotation Rotation) PoseOf(int[] v) =>
        (new Vector(UrWire.ToMillimetres(v[0]), UrWire.ToMillimetres(v[1]), UrWire.ToMillimetres(v[2])),
         Rotation.FromRotationVector(new Vector(UrWire.ToDegrees(v[3]), UrWire.ToDegrees(v[4]), UrWire.ToDegrees(v[5]))));
}

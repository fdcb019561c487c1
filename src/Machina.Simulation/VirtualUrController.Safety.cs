using System.Buffers.Binary;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>runtime_state values (RTDE guide).</summary>
    internal const uint Stopped = 1, Playing = 2, Paused = 4;

    /// <summary>safety_status values (RTDE guide).</summary>
    internal const int Normal = 1, ProtectiveStopped = 3, RobotEmergencyStopped = 7;

    /// <summary>The output integer register Machina's driver writes its instance number to (docs/protocol-ur.md).</summary>
    private const int InstanceRegisterNumber = 26;

    private string? _runtimeException;
    private int _safety = Normal;

    /// <summary>True while a program runs (playing or paused).</summary>
    public bool IsProgramRunning => Twin.State == UrScript.UrProgramState.Running;

    /// <summary>RTDE runtime_state now: 1 stopped, 2 playing, 4 paused.</summary>
    public uint RuntimeState => TwinRuntime(Twin);

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
        }
        Twin.Hold(); // the motion stops where the arm is; the program waits until it is played again
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

    /// <summary>
    /// The instance number in output_int_register_26: written by each of our driver programs when it starts, kept after it
    /// stops (registers keep their values), 0 until the first.
    /// </summary>
    public int InstanceRegister => (int)Twin.Io.GetNumber(UrScript.UrIoBanks.OutputIntRegisters, InstanceRegisterNumber);

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

    private protected override void AfterExecuted(object request, int id, CancellationToken token)
    {
        if (request is TwinAck ack)
        {
            AcknowledgeTwin(ack, token);
        }
    }

    /// <summary>An acknowledgement as the driver sends it: the id, one big-endian int32.</summary>
    private protected override byte[] AcknowledgementBytes(int id)
    {
        var bytes = new byte[4];
        BinaryPrimitives.WriteInt32BigEndian(bytes, id);
        return bytes;
    }

    /// <summary>A response (a code below -1) that never ends: more values than any response of the protocol carries.</summary>
    private protected override byte[] GarbageBytes(Random random)
    {
        var bytes = new byte[80 * 4];
        BinaryPrimitives.WriteInt32BigEndian(bytes, -100 - random.Next(1000));
        for (int i = 1; i < 80; i++)
        {
            BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(i * 4), random.Next(0, int.MaxValue));
        }
        return bytes;
    }

    private protected override bool InjectProtectiveStop() => ProtectiveStop();
}

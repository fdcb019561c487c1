using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

/// <summary>
/// The virtual UR's faults and inspection, at the seams a real controller has: the connection the running program opens back
/// to its host. Every <c>socket_open</c> of a program becomes the driver connection; what the program reads there is what it
/// received, and its write of a single integer outside a response (a negative code up to <c>RES_END</c>) is the acknowledgement
/// of what its arm just did: that write goes through the controller's fault plan (held, delayed, cut, lost, followed by a drop
/// or a protective stop) and is counted as executed. A protective stop holds the program at its next read until it is played.
/// </summary>
public sealed partial class VirtualUrController : IUrSocketSeam
{
    /// <summary>A response's last value (Machina's driver: RES_END).</summary>
    private const int ResponseEnd = int.MinValue;

    private UrSocket? _driver;
    private int _driverProgram;
    private bool _inResponse;
    private bool _awaitingHeader;

    /// <summary>True while the values of an instruction are read into <see cref="_readValues"/> (its header came).</summary>
    private bool _reading;

    /// <summary>
    /// The received instruction's values, header first, for the request log (one buffer kept for every instruction): the log
    /// keeps a copy and writes its text only when it is first read (<see cref="RequestText"/>), then keeps the text.
    /// </summary>
    private int[] _readValues = new int[16];
    private int _readCount;

    /// <summary>An acknowledgement the program is writing: executed by the arm already, sent (or not) by the fault plan.</summary>
    private sealed record TwinAck(int Id, int Program, TaskCompletionSource<bool> Done);

    void IUrSocketSeam.Opened(UrSocket socket, CancellationToken program)
    {
        lock (Gate)
        {
            _driver = socket;
            _driverProgram++;
            _inResponse = false;
            _awaitingHeader = true;
            _reading = false;
        }
        var client = new TcpClient();
        client.Client.Dispose();
        client.Client = socket.Connection;
        if (!AttachClient(client, socket.Held))
        {
            Pendant("the connection back to the host was refused");
        }
        // RTDE sends now what the program wrote before it connected (its registers): a host reads them as it greets it.
        WakeRtde();
    }

    void IUrSocketSeam.Read(UrSocket socket, UrList values)
    {
        if (values.Items[0] is not int n || n == 0)
        {
            return;
        }
        lock (Gate)
        {
            if (!ReferenceEquals(socket, _driver))
            {
                return;
            }
            if (_awaitingHeader && n == 2)
            {
                _readCount = 0;
                KeepRead(values, n);
                _reading = true;
                _awaitingHeader = false;
            }
            else if (_reading)
            {
                KeepRead(values, n);
            }
        }
        // A protective stop or a pause: the program waits here, before it runs what it read, until it is played again.
        Twin.WaitWhileHeld(socket.Program);
    }

    bool IUrSocketSeam.Send(UrSocket socket, ReadOnlySpan<byte> bytes, CancellationToken program)
    {
        if (bytes.Length != 4)
        {
            return socket.SendDirect(bytes);
        }
        int value = BinaryPrimitives.ReadInt32BigEndian(bytes);
        object entry;
        int generation;
        lock (Gate)
        {
            if (!ReferenceEquals(socket, _driver))
            {
                return socket.SendDirect(bytes);
            }
            if (_inResponse || value < -1)
            {
                _inResponse = value != ResponseEnd;
                return socket.SendDirect(bytes);
            }
            entry = _reading ? _readValues.AsSpan(0, _readCount).ToArray() : value.ToString(Num.Inv);
            _reading = false;
            _awaitingHeader = true;
            generation = _driverProgram;
        }
        // The program's own thread takes the acknowledgement through the fault plan (a held or delayed acknowledgement holds
        // the program, as a blocked socket write would): no hand-off to another thread per instruction. One that a restart
        // lost is never sent: the program waits there until it is replaced.
        var done = new TaskCompletionSource<bool>();
        AcknowledgeOnCaller(new TwinAck(value, generation, done), Math.Max(value, 0), entry, program);
        return TwinWait.For(done.Task, program);
    }

    /// <summary>Keeps the <paramref name="n"/> values of a read ([n, v1 … vn]: boxed integers, as socket_read_binary_integer gives them).</summary>
    private void KeepRead(UrList values, int n)
    {
        if (_readCount + n > _readValues.Length)
        {
            Array.Resize(ref _readValues, Math.Max(_readValues.Length * 2, _readCount + n));
        }
        for (int i = 1; i <= n; i++)
        {
            _readValues[_readCount++] = values.Items[i] is int v ? v : -1; // always an int here: the read's own values
        }
    }

    /// <summary>A received instruction's log text (its values, header first, space-separated), written when the log is first read (the log keeps it).</summary>
    private protected override string RequestText(object entry)
    {
        if (entry is not int[] read)
        {
            return base.RequestText(entry);
        }
        var text = new StringBuilder(read.Length * 8);
        for (int i = 0; i < read.Length; i++)
        {
            if (i > 0)
            {
                text.Append(' ');
            }
            text.Append(read[i].ToString(Num.Inv));
        }
        return text.ToString();
    }

    /// <summary>Sends an executed acknowledgement through the fault plan, unless its program was replaced since (nobody listens for it then).</summary>
    private void AcknowledgeTwin(TwinAck ack, CancellationToken token)
    {
        try
        {
            bool current;
            lock (Gate)
            {
                current = ack.Program == _driverProgram;
            }
            if (current)
            {
                Acknowledge(AcknowledgementBytes(ack.Id), Math.Max(ack.Id, 0), token);
            }
            ack.Done.TrySetResult(current);
        }
        finally
        {
            ack.Done.TrySetResult(false);
        }
    }

    /// <summary>Holds the twin's program (a protective stop or pause): its motion stops where the arm is; false when already held.</summary>
    private bool HoldTwin() => Twin.Hold();

    /// <summary>Lets the twin's held program go on; false when it was not held.</summary>
    private bool ReleaseTwin() => Twin.Release();

    private bool TwinHeld => Twin.IsHeld;

    /// <summary>How long the twin's motion in progress takes (a test waits for its timer), or null when the arm stands.</summary>
    internal TimeSpan? MotionDuration => Twin.Motion?.Duration;

    /// <summary>The robot as the twin's arm and outputs have it now (speeds and blend are the driver's own variables: kept from the start).</summary>
    private static VirtualUrState TwinState(UrTwinController twin, VirtualUrState basis)
    {
        var seen = new TwinObservation();
        seen.DigitalBank(twin.Io, UrIoBanks.StandardOut, "", 0);
        seen.DigitalBank(twin.Io, UrIoBanks.ToolOut, "tool ", 0);
        seen.AnalogBank(twin.Io, UrIoBanks.AnalogOut, 0);
        return seen.Apply(basis, twin.Arm, twin.JointsNow(), twin.Arm.ToolCenter) with { Payload = twin.Arm.PayloadKg };
    }
}

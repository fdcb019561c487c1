using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>Robot message (client interfaces): message type 20; its runtime exception kind is 10.</summary>
    private const byte RobotMessageType = 20, RuntimeExceptionKind = 10;

    /// <summary>Source of a robot message sent by the controller itself (its program): -2.</summary>
    private const sbyte ControllerSource = -2;

    /// <summary>
    /// A runtime exception as the primary and secondary client interfaces send it: int size, byte 20, uint64 timestamp (ms), byte
    /// source, byte 10, int script line, int script column, then the text (client interface manual, "Messages").
    /// </summary>
    internal static byte[] RuntimeExceptionMessage(ulong timestamp, int line, int column, string text)
    {
        byte[] words = Encoding.UTF8.GetBytes(text);
        var bytes = new byte[23 + words.Length];
        BinaryPrimitives.WriteInt32BigEndian(bytes, bytes.Length);
        bytes[4] = RobotMessageType;
        BinaryPrimitives.WriteUInt64BigEndian(bytes.AsSpan(5), timestamp);
        bytes[13] = unchecked((byte)ControllerSource);
        bytes[14] = RuntimeExceptionKind;
        BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(15), line);
        BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(19), column);
        words.CopyTo(bytes, 23);
        return bytes;
    }

    /// <summary>Sends a runtime error of the interpreter's program to every connection on the script ports, before its sockets close.</summary>
    private void SendTwinRuntimeError(int line, string reason)
    {
        byte[] bytes = RuntimeExceptionMessage((ulong)Uptime.TotalMilliseconds, line, 0, reason);
        NetworkStream[] streams;
        lock (Gate)
        {
            _runtimeException = reason;
            streams = [.. _scriptStreams];
        }
        SendToStateClients(() => bytes);
        foreach (NetworkStream stream in streams)
        {
            try
            {
                stream.Write(bytes);
            }
            catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException)
            {
                // That client is gone.
            }
        }
    }
}

using System.Buffers.Binary;
using System.Text;

namespace Machina;

/// <summary>
/// The runtime exception messages a UR controller's primary and secondary client interfaces (ports 30001 and 30002) send
/// when a program stops on an error: a robot message package (int32 size, type 20, uint64 timestamp, int8 source, message
/// type 10, int32 script line, int32 script column, then the text). Other packages on those ports are skipped.
/// </summary>
internal static class UrRobotMessage
{
    /// <summary>Package type of a robot message.</summary>
    public const byte RobotMessage = 20;

    /// <summary>Robot message type of a runtime exception.</summary>
    public const byte RuntimeExceptionType = 10;

    /// <summary>Bytes before the text: size 4, type 1, timestamp 8, source 1, message type 1, line 4, column 4.</summary>
    private const int Header = 23;

    /// <summary>Largest package accepted; anything larger is not this protocol.</summary>
    public const int MaxPackage = 1 << 20;

    /// <summary>A runtime exception package with <paramref name="text"/> at a script line and column.</summary>
    public static byte[] RuntimeException(ulong timestamp, int line, int column, string text)
    {
        byte[] chars = Encoding.ASCII.GetBytes(text);
        var bytes = new byte[Header + chars.Length];
        BinaryPrimitives.WriteInt32BigEndian(bytes, bytes.Length);
        bytes[4] = RobotMessage;
        BinaryPrimitives.WriteUInt64BigEndian(bytes.AsSpan(5), timestamp);
        bytes[13] = unchecked((byte)-2); // source: the controller
        bytes[14] = RuntimeExceptionType;
        BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(15), line);
        BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(19), column);
        chars.CopyTo(bytes.AsSpan(Header));
        return bytes;
    }

    /// <summary>
    /// Reads packages from a script port's stream, however TCP chunks them, and hands each runtime exception (its text with
    /// its line) to <paramref name="onException"/>. Stops reading, for good, at a package size no controller sends.
    /// </summary>
    internal sealed class Reader(Action<string> onException) : ILinkReceiver
    {
        private readonly List<byte> _pending = [];
        private bool _lost;

        /// <inheritdoc/>
        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (_lost)
            {
                return;
            }
            _pending.AddRange(data);
            while (_pending.Count >= 5)
            {
                int size = BinaryPrimitives.ReadInt32BigEndian([_pending[0], _pending[1], _pending[2], _pending[3]]);
                if (size < 5 || size > MaxPackage)
                {
                    _lost = true; // not the client interface (e.g. the real-time port): nothing to read here
                    _pending.Clear();
                    return;
                }
                if (_pending.Count < size)
                {
                    return;
                }
                byte[] package = [.. _pending.GetRange(0, size)];
                _pending.RemoveRange(0, size);
                if (package[4] == RobotMessage && size >= Header && package[14] == RuntimeExceptionType)
                {
                    int line = BinaryPrimitives.ReadInt32BigEndian(package.AsSpan(15));
                    string text = Encoding.ASCII.GetString(package, Header, size - Header);
                    onException(line > 0 ? $"{text} (driver script line {line.ToString(Num.Inv)})" : text);
                }
            }
        }

        /// <inheritdoc/>
        public void OnClosed(Exception? error)
        {
        }
    }
}

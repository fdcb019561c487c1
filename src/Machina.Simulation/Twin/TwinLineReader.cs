using System.Text;

namespace Machina.Simulation.Twin;

/// <summary>
/// Reads the lines of a text port (one command per line, as the UR dashboard server takes them) with a length cap: a line longer
/// than <see cref="MaxLength"/> bytes is refused as soon as it passes the cap, without holding more of it. Each byte is looked at
/// once.
/// </summary>
internal sealed class TwinLineReader(Stream stream, int maxLength)
{
    private readonly byte[] _buffer = new byte[Math.Max(maxLength + 2, 256)];
    private int _start;
    private int _end;
    private int _scanned;

    /// <summary>The longest line taken, in bytes (without its line break).</summary>
    public int MaxLength { get; } = maxLength;

    /// <summary>
    /// The next line (Latin-1, without its <c>\n</c> or <c>\r\n</c>), or null when the client closed the connection; throws
    /// <see cref="InvalidDataException"/> when the line is longer than <see cref="MaxLength"/>.
    /// </summary>
    public async Task<string?> ReadLineAsync(CancellationToken cancellationToken)
    {
        while (true)
        {
            int newline = Array.IndexOf(_buffer, (byte)'\n', _scanned, _end - _scanned);
            if (newline >= 0)
            {
                int length = newline - _start;
                if (length > 0 && _buffer[newline - 1] == '\r')
                {
                    length--;
                }
                if (length > MaxLength)
                {
                    throw TooLong();
                }
                string line = Encoding.Latin1.GetString(_buffer, _start, length);
                _start = _scanned = newline + 1;
                return line;
            }
            _scanned = _end;
            if (_end - _start > MaxLength + 1)
            {
                throw TooLong();
            }
            if (_end == _buffer.Length)
            {
                Array.Copy(_buffer, _start, _buffer, 0, _end - _start);
                _end -= _start;
                _scanned -= _start;
                _start = 0;
            }
            int n = await stream.ReadAsync(_buffer.AsMemory(_end), cancellationToken).ConfigureAwait(false);
            if (n == 0)
            {
                return null;
            }
            _end += n;
        }
    }

    private InvalidDataException TooLong() => new($"a line longer than {MaxLength} bytes");
}

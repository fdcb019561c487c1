using System.Text;

namespace Machina;

/// <summary>
/// Writes lines to a stream in ASCII (<see cref="Encoding.ASCII"/>: a character outside it becomes <c>?</c>), each line's characters
/// narrowed straight into one byte buffer that goes to the stream when full: the bytes a <see cref="StreamWriter"/> over
/// <see cref="Encoding.ASCII"/> writes, without its character buffer and encoder (a copy of every character and a second pass over
/// it; a 10^6-line script is 200 MB).
/// </summary>
internal sealed class AsciiFileSink : LineSink, IDisposable
{
    private readonly Stream _stream;
    private readonly byte[] _newLine;
    private byte[] _buffer;
    private int _used;

    /// <summary>A sink over <paramref name="stream"/>, which it closes when disposed.</summary>
    internal AsciiFileSink(Stream stream, string newLine, int bufferSize = 1 << 17)
    {
        _stream = stream;
        NewLine = newLine;
        _newLine = Encoding.ASCII.GetBytes(newLine);
        _buffer = new byte[Math.Max(bufferSize, 256)];
    }

    /// <summary>What ends each line.</summary>
    internal string NewLine { get; }

    /// <summary>The stream the bytes go to (after <see cref="Flush"/>, all of them).</summary>
    internal Stream Stream => _stream;

    /// <summary>A seekable stream can be emptied and written again.</summary>
    internal override bool CanStartOver => _stream.CanSeek;

    internal override void StartOver()
    {
        if (!CanStartOver)
        {
            base.StartOver();
        }
        _used = 0;
        _stream.SetLength(0);
        _stream.Position = 0;
    }

    internal override void Add(string line) => Add(line.AsSpan());

    internal override void Add(ReadOnlySpan<char> line)
    {
        if (_buffer.Length - _used < line.Length + _newLine.Length)
        {
            Flush();
            if (_buffer.Length < line.Length + _newLine.Length)
            {
                _buffer = new byte[line.Length + _newLine.Length];
            }
        }
        Span<byte> free = _buffer.AsSpan(_used);
        if (System.Text.Ascii.FromUtf16(line, free, out int written) != System.Buffers.OperationStatus.Done)
        {
            // Not all ASCII: the encoder's own replacement for the whole line (a surrogate pair is one character).
            written = Encoding.ASCII.GetBytes(line, free);
        }
        _newLine.CopyTo(free[written..]);
        _used += written + _newLine.Length;
    }

    /// <summary>The buffer's free space itself: the line is written in place and <see cref="EndAscii"/> only ends it.</summary>
    internal override Span<byte> BeginAscii(int most)
    {
        int room = most + _newLine.Length;
        if (_buffer.Length - _used < room)
        {
            Flush();
            if (_buffer.Length < room)
            {
                _buffer = new byte[room];
            }
        }
        return _buffer.AsSpan(_used, most);
    }

    internal override void EndAscii(int length)
    {
        _newLine.CopyTo(_buffer.AsSpan(_used + length));
        _used += length + _newLine.Length;
    }

    internal override void Add(StringBuilder line)
    {
        int start = _used;
        foreach (ReadOnlyMemory<char> chunk in line.GetChunks())
        {
            ReadOnlySpan<char> part = chunk.Span;
            if (_buffer.Length - _used < part.Length + _newLine.Length
                || System.Text.Ascii.FromUtf16(part, _buffer.AsSpan(_used), out int written) != System.Buffers.OperationStatus.Done)
            {
                _used = start; // a long or non-ASCII line: written whole, as a string
                Add(line.ToString());
                return;
            }
            _used += written;
        }
        _newLine.CopyTo(_buffer.AsSpan(_used));
        _used += _newLine.Length;
    }

    /// <summary>Writes the buffered bytes to the stream.</summary>
    internal void Flush()
    {
        if (_used > 0)
        {
            _stream.Write(_buffer, 0, _used);
            _used = 0;
        }
    }

    /// <summary>Writes what is buffered and closes the stream (even when the write fails, as <see cref="StreamWriter"/> does).</summary>
    public void Dispose()
    {
        try
        {
            Flush();
        }
        finally
        {
            _used = 0;
            _stream.Dispose();
        }
    }
}

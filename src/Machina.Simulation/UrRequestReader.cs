using System.Buffers.Binary;

namespace Machina.Simulation;

/// <summary>
/// Reads the instructions a host sends to a UR driver program: big-endian int32 values, each instruction an id, a code and as
/// many parameters as the code takes (spec online §7.3), however TCP chunks them. Never reads more than one instruction ahead
/// and never holds more than <see cref="BufferSize"/> bytes, whatever the stream says.
/// </summary>
internal sealed class UrRequestReader(Stream stream, VirtualUrController.DriverKind kind, int program)
{
    /// <summary>Bytes buffered at most.</summary>
    internal const int BufferSize = 8192;

    /// <summary>Most integers one read asks for (the longest instruction, set tool, has 7 parameters).</summary>
    internal const int MaxValues = 16;

    private readonly byte[] _buffer = new byte[BufferSize];
    private readonly int[] _values = new int[MaxValues];
    private int _start;
    private int _length;

    /// <summary>What the last <see cref="ReadAsync"/> found when it returned null: the header of an instruction the stream ended inside, if any.</summary>
    internal (int Id, int Code)? EndedInside { get; private set; }

    /// <summary>
    /// The next instruction, or null when the stream ended (<see cref="EndedInside"/> tells whether inside one). An instruction
    /// with a code our driver does not know comes back with <see cref="UrRequest.Halts"/>: the driver reads nothing after it.
    /// </summary>
    internal async Task<UrRequest?> ReadAsync(CancellationToken token)
    {
        if (!await FillAsync(2, token).ConfigureAwait(false))
        {
            return null;
        }
        int id = _values[0], code = _values[1];
        int count = VirtualUrController.ParameterCount(code, kind);
        if (count < 0)
        {
            return new UrRequest(id, code, [], program, Halts: true);
        }
        if (count > 0 && !await FillAsync(count, token).ConfigureAwait(false))
        {
            EndedInside = (id, code);
            return null;
        }
        return new UrRequest(id, code, _values.AsSpan(0, count).ToArray(), program);
    }

    /// <summary>Reads <paramref name="count"/> values (at most <see cref="MaxValues"/>) into the values; false when the stream ended first.</summary>
    private async Task<bool> FillAsync(int count, CancellationToken token)
    {
        if (count is < 0 or > MaxValues)
        {
            throw new ArgumentOutOfRangeException(nameof(count), count, $"A read takes 0 to {MaxValues} values.");
        }
        while (_length < count * 4)
        {
            if (_start > 0)
            {
                Array.Copy(_buffer, _start, _buffer, 0, _length);
                _start = 0;
            }
            int n = await stream.ReadAsync(_buffer.AsMemory(_length), token).ConfigureAwait(false);
            if (n == 0)
            {
                return false;
            }
            _length += n;
        }
        for (int i = 0; i < count; i++)
        {
            _values[i] = BinaryPrimitives.ReadInt32BigEndian(_buffer.AsSpan(_start + i * 4));
        }
        _start += count * 4;
        _length -= count * 4;
        if (_length == 0)
        {
            _start = 0;
        }
        return true;
    }
}

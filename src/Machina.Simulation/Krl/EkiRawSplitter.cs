using System.Text;

namespace Machina.Simulation.Krl;

/// <summary>
/// Cuts the bytes of a channel in raw mode into records as EthernetKRL stores them, uninterpreted: a BYTE element every
/// <see cref="EkiRawElement.Size"/> bytes, a STREAM element at each end string (the record without it). A record is kept as text
/// of one character per byte (Latin-1), as EKI_GetString reads it. A STREAM longer than its Size without an end string is
/// refused with <see cref="FormatException"/> (the connection is closed).
/// </summary>
internal sealed class EkiRawSplitter(EkiRawElement element)
{
    private readonly List<byte> _pending = [];
    private readonly int _longestEnd = element.EndStrings.Count == 0 ? 0 : element.EndStrings.Max(e => e.Length);

    /// <summary>The complete records in what has arrived so far.</summary>
    public List<string> Append(ReadOnlySpan<byte> bytes)
    {
        var records = new List<string>();
        foreach (byte b in bytes)
        {
            _pending.Add(b);
            if (!element.Stream)
            {
                if (_pending.Count == element.Size)
                {
                    records.Add(Take(_pending.Count));
                }
                continue;
            }
            foreach (byte[] end in element.EndStrings)
            {
                if (EndsWith(end))
                {
                    records.Add(Take(_pending.Count - end.Length));
                    break;
                }
            }
            if (_pending.Count > element.Size + _longestEnd)
            {
                throw new FormatException($"a STREAM record of {element.Tag} is longer than its Size of {element.Size} bytes without an end string");
            }
        }
        return records;
    }

    private bool EndsWith(byte[] end)
    {
        if (_pending.Count < end.Length)
        {
            return false;
        }
        for (int i = 0; i < end.Length; i++)
        {
            if (_pending[_pending.Count - end.Length + i] != end[i])
            {
                return false;
            }
        }
        return true;
    }

    private string Take(int length)
    {
        string record = Encoding.Latin1.GetString(_pending.GetRange(0, length).ToArray());
        _pending.Clear();
        return record;
    }

    /// <summary>The bytes EKI_Send writes for <paramref name="data"/>: BYTE exactly Size bytes (cut, or filled with 0), STREAM the data and its first end string.</summary>
    public static byte[] Record(EkiRawElement element, string data)
    {
        byte[] bytes = Encoding.Latin1.GetBytes(data);
        if (!element.Stream)
        {
            Array.Resize(ref bytes, element.Size);
            return bytes;
        }
        return [.. bytes.AsSpan(0, Math.Min(bytes.Length, element.Size)), .. element.EndStrings[0]];
    }
}

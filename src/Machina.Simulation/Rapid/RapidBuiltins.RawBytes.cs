using System.Buffers.Binary;
using System.Globalization;
using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Raw bytes (RAPID reference, "rawbytes"): PackRawBytes, UnpackRawBytes, CopyRawBytes, ClearRawBytes, RawBytesLen, and the raw
/// forms of SocketSend and SocketReceive. Integers and floats are little-endian unless <c>\Network</c> asks for big-endian.
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> RawBytes() =>
    [
        Instruction("ClearRawBytes", [P("RawData", "rawbytes"), Opt("FromIndex", "num")], call =>
        {
            var raw = (RapidRawBytes)call.Value(0);
            int from = call.Has(1) ? RawIndex(call, call.Num(1), 0) : 1;
            Array.Clear(raw.Bytes, from - 1, RapidRawBytes.Capacity - from + 1);
            raw.Length = Math.Min(raw.Length, from - 1);
        }),
        Instruction("CopyRawBytes", [P("FromRawData", "rawbytes"), P("FromIndex", "num"), P("ToRawData", "rawbytes"), P("ToIndex", "num"), Opt("NoOfBytes", "num")], call =>
        {
            var from = (RapidRawBytes)call.Value(0);
            var to = (RapidRawBytes)call.Value(2);
            int fromIndex = RawIndex(call, call.Num(1), 0), toIndex = RawIndex(call, call.Num(3), 0);
            int count = call.Has(4) ? (int)call.Num(4) : from.Length - fromIndex + 1;
            if (count < 0 || fromIndex - 1 + count > RapidRawBytes.Capacity || toIndex - 1 + count > RapidRawBytes.Capacity)
            {
                throw call.Error(RapidErrorNumbers.OutOfBounds, $"CopyRawBytes: {count} bytes do not fit between index 1 and {RapidRawBytes.Capacity}");
            }
            byte[] chunk = from.Bytes.AsSpan(fromIndex - 1, count).ToArray();
            to.Write(toIndex, chunk);
        }),
        Function("RawBytesLen", "num", [P("RawData", "rawbytes")], call => (double)((RapidRawBytes)call.Value(0)).Length),
        Instruction("PackRawBytes", [P("Value", null), P("RawData", "rawbytes"), Sw("Network"), P("StartIndex", "num"),
            Sw("Hex1"), Opt("IntX", "inttypes"), Sw("Float4"), Sw("ASCII")], call =>
        {
            var raw = (RapidRawBytes)call.Value(1);
            object value = call.Value(0);
            byte[] bytes = PackedBytes(call, value, call.Has(2));
            raw.Write(RawIndex(call, call.Num(3), bytes.Length), bytes);
        }),
        Instruction("UnpackRawBytes", [P("RawData", "rawbytes"), Sw("Network"), P("StartIndex", "num"), P("Value", null, true),
            Sw("Hex1"), Opt("IntX", "inttypes"), Sw("Float4"), Opt("ASCII", "num")], call =>
        {
            var raw = (RapidRawBytes)call.Value(0);
            bool network = call.Has(1);
            int size = call.Has(4) ? 1 : call.Has(5) ? Math.Abs((int)call.Num(5)) : call.Has(6) ? 4 : call.Has(7) ? (int)call.Num(7)
                : throw ArgumentError(call, "UnpackRawBytes needs one of \\Hex1, \\IntX, \\Float4 or \\ASCII");
            int start = RawIndex(call, call.Num(2), size);
            if (start - 1 + size > raw.Length)
            {
                throw call.Error(RapidErrorNumbers.OutOfBounds, $"UnpackRawBytes: bytes {start}..{start + size - 1} are beyond the {raw.Length} bytes of the data");
            }
            ReadOnlySpan<byte> b = raw.Bytes.AsSpan(start - 1, size);
            object result;
            if (call.Has(4))
            {
                result = b[0].ToString("X2", CultureInfo.InvariantCulture);
            }
            else if (call.Has(5))
            {
                result = (double)ReadInteger(b, (int)call.Num(5), network);
            }
            else if (call.Has(6))
            {
                int bits = network ? BinaryPrimitives.ReadInt32BigEndian(b) : BinaryPrimitives.ReadInt32LittleEndian(b);
                result = (double)BitConverter.Int32BitsToSingle(bits);
            }
            else
            {
                string text = Encoding.Latin1.GetString(b);
                result = call.TypeOf(3) is { Element.IsNumeric: true } ? (double)b[0] : text;
            }
            call.Set(3, result);
        }),
    ];

    /// <summary>A 1-based index of raw bytes with room for <paramref name="size"/> bytes from it; else ERR_OUTOFBND.</summary>
    private static int RawIndex(RapidCall call, double index, int size)
    {
        if (index < 1 || index != Math.Floor(index) || index - 1 + size > RapidRawBytes.Capacity)
        {
            throw call.Error(RapidErrorNumbers.OutOfBounds, $"the raw-byte index {RapidValues.FormatNumber(index)} is outside 1..{RapidRawBytes.Capacity} for {size} byte(s)");
        }
        return (int)index;
    }

    /// <summary>The bytes PackRawBytes writes for <paramref name="value"/> as its switches say.</summary>
    private static byte[] PackedBytes(RapidCall call, object value, bool network)
    {
        if (call.Has(4))
        {
            return [byte.Parse(value as string ?? RapidValues.ToText(value), NumberStyles.HexNumber, CultureInfo.InvariantCulture)];
        }
        if (call.Has(5))
        {
            return IntegerBytes(call, (double)value, (int)call.Num(5), network);
        }
        if (call.Has(6))
        {
            var bytes = new byte[4];
            int bits = BitConverter.SingleToInt32Bits((float)(double)value);
            if (network)
            {
                BinaryPrimitives.WriteInt32BigEndian(bytes, bits);
            }
            else
            {
                BinaryPrimitives.WriteInt32LittleEndian(bytes, bits);
            }
            return bytes;
        }
        if (call.Has(7))
        {
            return value is string s ? Encoding.Latin1.GetBytes(s) : [(byte)(double)value];
        }
        throw ArgumentError(call, "PackRawBytes needs one of \\Hex1, \\IntX, \\Float4 or \\ASCII");
    }

    private static byte[] IntegerBytes(RapidCall call, double value, int type, bool network)
    {
        (long min, long max) = type switch
        {
            1 => (0L, byte.MaxValue), 2 => (0L, ushort.MaxValue), 4 => (0L, uint.MaxValue), 8 => (0L, long.MaxValue),
            -1 => (sbyte.MinValue, sbyte.MaxValue), -2 => (short.MinValue, short.MaxValue), -4 => (int.MinValue, int.MaxValue), -8 => (long.MinValue, long.MaxValue),
            _ => throw ArgumentError(call, $"\\IntX: {RapidValues.FormatNumber(type)} is not an inttypes value (USINT, UINT, UDINT, ULINT, SINT, INT, DINT, LINT)"),
        };
        if (value != Math.Floor(value) || value < min || value > max)
        {
            throw ArgumentError(call, $"PackRawBytes: {RapidValues.FormatNumber(value)} is not an integer of that type");
        }
        var bytes = new byte[Math.Abs(type)];
        long v = (long)value;
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[network ? bytes.Length - 1 - i : i] = (byte)(v >> (8 * i));
        }
        return bytes;
    }

    private static long ReadInteger(ReadOnlySpan<byte> b, int type, bool network)
    {
        long v = 0;
        for (int i = 0; i < b.Length; i++)
        {
            v |= (long)b[network ? b.Length - 1 - i : i] << (8 * i);
        }
        if (type < 0 && b.Length < 8 && (v & (1L << (8 * b.Length - 1))) != 0)
        {
            v -= 1L << (8 * b.Length);
        }
        return v;
    }

    /// <summary>SocketReceive \RawData or \Data: what has arrived (waiting for at least one byte), up to 1024 bytes or \ReadNoOfBytes, into the raw bytes from index 1.</summary>
    private static void ReceiveRaw(RapidCall call, Socket connection, double seconds)
    {
        int wanted = call.Has(4) ? (int)call.Num(4) : 0;
        if ((call.Has(4) && wanted < 1) || wanted > RapidRawBytes.Capacity)
        {
            throw ArgumentError(call, $"SocketReceive: \\ReadNoOfBytes {wanted} is outside 1..{RapidRawBytes.Capacity}");
        }
        byte[] received = Encoding.Latin1.GetBytes(ReceiveText(call, connection, wanted > 0 ? wanted : RapidRawBytes.Capacity, seconds));
        StoreReceived(call, 2, received);
        if (call.Has(5))
        {
            call.Set(5, (double)received.Length);
        }
    }

    /// <summary>Puts received bytes into the \RawData (parameter <paramref name="raw"/>, from index 1) or the \Data array (the next parameter).</summary>
    private static void StoreReceived(RapidCall call, int raw, byte[] received)
    {
        if (call.Has(raw))
        {
            var bytes = (RapidRawBytes)call.Value(raw);
            Array.Clear(bytes.Bytes);
            bytes.Length = 0;
            bytes.Write(1, received);
            return;
        }
        var array = (RapidArray)call.Value(raw + 1);
        RapidCell? cell = call.DataCell(raw + 1);
        cell?.BeginWrite(); // the elements are written in place: RWS reads the array again meanwhile
        for (int i = 0; i < array.Items.Length; i++)
        {
            array.Items[i] = i < received.Length ? (double)received[i] : 0.0;
        }
        cell?.EndWrite();
    }

    /// <summary>The bytes SocketSend sends: \Str, \RawData (its length, or \NoOfBytes) or \Data (an array of bytes, or \NoOfBytes of them).</summary>
    private static byte[] SendBytes(RapidCall call, int first = 1)
    {
        if (call.Has(first))
        {
            return Encoding.Latin1.GetBytes(call.Str(first));
        }
        if (call.Has(first + 1))
        {
            var raw = (RapidRawBytes)call.Value(first + 1);
            int count = call.Has(first + 3) ? (int)call.Num(first + 3) : raw.Length;
            return count < 0 || count > raw.Length
                ? throw ArgumentError(call, $"SocketSend: \\NoOfBytes {count} is more than the {raw.Length} bytes of the data")
                : raw.Bytes[..count];
        }
        if (call.Has(first + 2) && call.Value(first + 2) is RapidArray array)
        {
            int count = call.Has(first + 3) ? (int)call.Num(first + 3) : array.Items.Length;
            return [.. array.Items.Take(count).Select(v => (byte)(double)v)];
        }
        throw ArgumentError(call, "SocketSend needs \\Str, \\RawData or \\Data");
    }
}

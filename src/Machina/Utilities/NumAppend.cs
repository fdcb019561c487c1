using System.Numerics;
using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// The one writer of numbers in programs: fast, allocation-free, for compilers that write millions of values. Its one policy
/// for every language: rounded to the language's decimals (midpoint to even, −0 as 0), always in plain decimal notation
/// (0.00001, never 1E-05; a value of 10^15 units of the last decimal or more as its 15 significant digits then zeros, 1E+20
/// as 100000000000000000000), which every robot language and G-code reads; a value no language can hold (NaN, an infinity)
/// is refused, never written. The same digits as <see cref="Num.F(double, int)"/> wherever that writes plain notation.
/// </summary>
/// <remarks>
/// <see cref="Num"/> writes numbers for people (messages, logs) in .NET's general format; <see cref="NumShortest"/> writes the
/// shortest text of a user's number (instructions, warnings), and <see cref="NumParse"/> reads it back. All four share
/// <see cref="WriteDecimal"/> and the powers of ten here.
/// </remarks>
internal static class NumAppend
{
    /// <summary>10^0 to 10^15 as doubles, all exact: the scales of <see cref="MaxDecimals"/> decimals and the divisors <see cref="NumParse"/> needs.</summary>
    internal static readonly double[] Pow10 = [1, 10, 100, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15];

    /// <summary>The most decimals this writer writes (its scaled values are whole numbers below 10^15 written with them).</summary>
    internal const int MaxDecimals = 9;

    /// <summary>Appends <paramref name="value"/> rounded to <paramref name="decimals"/> (0–9) decimals, trailing zeros removed.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static StringBuilder AppendFixed(this StringBuilder sb, double value, int decimals)
    {
        if (!TryScale(value, decimals, out double scaled))
        {
            return AppendHuge(sb, value, decimals);
        }
        // Written straight into the builder's free space (ScaledDecimal), not into a buffer and copied.
        return sb.Append(Num.Inv, $"{new ScaledDecimal(scaled, decimals)}");
    }

    /// <summary>The text <see cref="AppendFixed"/> appends, as a string.</summary>
    internal static string Format(double value, int decimals) => new StringBuilder(24).AppendFixed(value, decimals).ToString();

    /// <summary>
    /// A value of 10^15 units of the last decimal or more: its 15 significant digits, then zeros, in plain notation (no
    /// language reads every exponent form: G-code none). NaN and infinities are refused: a program must never carry them.
    /// </summary>
    private static StringBuilder AppendHuge(StringBuilder sb, double value, int decimals)
    {
        if (!double.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, "A program or message cannot carry a number that is not finite.");
        }
        return sb.Append(Num.Clean(Math.Round(value, decimals)).ToString("0." + new string('#', Math.Max(1, decimals)), Num.Inv));
    }

    /// <summary>
    /// <paramref name="value"/> · 10^<paramref name="decimals"/> (0–9) rounded to a whole number, halves to even, as
    /// <see cref="TryWriteScaled"/> writes it; false when it is 10^15 or more in size, or not finite.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static bool TryScale(double value, int decimals, out double scaled)
    {
        scaled = RoundEven(value * Pow10[decimals]);
        return Math.Abs(scaled) < 1e15;
    }

    /// <summary>Characters enough for any number this class or <see cref="Num.F(double, int)"/> writes.</summary>
    internal const int MaxChars = 32;

    /// <summary>
    /// Writes <paramref name="value"/> rounded to <paramref name="decimals"/> (0–9) decimals into <paramref name="destination"/>
    /// (at least <see cref="MaxChars"/> long) in plain decimal notation and returns the number of characters, or −1 when the
    /// rounded value has more than 15 significant digits, or is not finite, and the caller must format it another way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteScaled(Span<char> destination, double value, int decimals) => WriteScaled<char>(destination, value, decimals);

    /// <summary>
    /// Writes the ASCII bytes of what <see cref="TryWriteScaled"/> writes as characters (for lines that go
    /// to a file as bytes: <see cref="LineSink.BeginAscii"/>); returns their count or −1 as it does.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteScaledAscii(Span<byte> destination, double value, int decimals) => WriteScaled<byte>(destination, value, decimals);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int WriteScaled<T>(Span<T> destination, double value, int decimals)
        where T : unmanaged, IBinaryInteger<T>
    {
        // Math.Round(value, decimals) scales, rounds to even and scales back; doing the first two steps here gives the
        // same digits as an integer, which prints exactly while it has at most 15 significant digits.
        if (!TryScale(value, decimals, out double scaled))
        {
            return -1;
        }
        return WriteDecimal(destination, scaled < 0, (long)Math.Abs(scaled), decimals);
    }

    /// <summary>
    /// Writes the three coordinates of <paramref name="position"/>, each times <paramref name="scale"/> as <see cref="TryWriteScaled"/>
    /// writes it, <paramref name="separator"/> between them, at <paramref name="at"/> (room for three numbers and two
    /// separators); returns the position after them, or −1 when one is too large for these digits and the caller must write
    /// the line another way. The move lines of RAPID and URScript begin so.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteCoordinates(Span<char> destination, int at, Vector position, double scale, int decimals, ReadOnlySpan<char> separator) =>
        WriteCoordinates<char>(destination, at, position, scale, decimals, separator);

    /// <summary>
    /// Writes the ASCII bytes of what <see cref="TryWriteCoordinates"/> writes as characters; returns the position after them,
    /// or −1 as it does.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteCoordinatesAscii(Span<byte> destination, int at, Vector position, double scale, int decimals, ReadOnlySpan<byte> separator) =>
        WriteCoordinates<byte>(destination, at, position, scale, decimals, separator);

    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int WriteCoordinates<T>(Span<T> destination, int at, Vector position, double scale, int decimals, ReadOnlySpan<T> separator)
        where T : unmanaged, IBinaryInteger<T>
    {
        ReadOnlySpan<double> xyz = [position.X, position.Y, position.Z];
        for (int i = 0; i < xyz.Length; i++)
        {
            if (i > 0)
            {
                separator.CopyTo(destination[at..]);
                at += separator.Length;
            }
            int written = WriteScaled(destination[at..], xyz[i] * scale, decimals);
            if (written < 0)
            {
                return -1;
            }
            at += written;
        }
        return at;
    }

    /// <summary>
    /// Writes <paramref name="mantissa"/> · 10^−<paramref name="decimals"/> (0–9 decimals; the mantissa below 10^18) in plain
    /// decimal notation, trailing zeros of the fraction removed, '-' first when <paramref name="negative"/> and the number is not
    /// 0; returns the number of characters. Digits are written by hand: the general integer formatter took about 5 % of a RAPID compile.
    /// </summary>
    /// <remarks>Characters (<see cref="char"/>) or ASCII bytes (<see cref="byte"/>): the same digits either way.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int WriteDecimal<T>(Span<T> destination, bool negative, long mantissa, int decimals)
        where T : unmanaged, IBinaryInteger<T>
    {
        int at = 0;
        if (negative && mantissa != 0)
        {
            destination[at++] = T.CreateTruncating('-');
        }
        // Millimetres (3 decimals) and metres (6 decimals) below 1000, most numbers of most programs: three digits at a time
        // (packed characters: the first in the low bits, which is the first in memory on little-endian processors).
        if (BitConverter.IsLittleEndian && decimals == 3 && (ulong)mantissa < 1_000_000)
        {
            uint thousandths = (uint)mantissa;
            uint units = thousandths / 1000;
            return WriteFraction(destination, WriteBelowThousand(destination, at, units), thousandths - units * 1000, 0);
        }
        if (BitConverter.IsLittleEndian && decimals == 6 && (ulong)mantissa < 1_000_000_000)
        {
            uint millionths = (uint)mantissa;
            uint units = millionths / 1_000_000;
            uint millionthsOfUnit = millionths - units * 1_000_000;
            uint high = millionthsOfUnit / 1000;
            return WriteFraction(destination, WriteBelowThousand(destination, at, units), high, millionthsOfUnit - high * 1000);
        }
        // Divisions by constants: the processor's divide by a power chosen at run time cost more than the digits themselves.
        long whole = DivPow10(mantissa, decimals);
        long fraction = mantissa - whole * (long)Powers[decimals];
        at += WriteDigits(destination[at..], whole, 1);
        if (fraction == 0)
        {
            return at;
        }
        int digits = decimals;
        while (fraction % 10 == 0)
        {
            fraction /= 10;
            digits--;
        }
        destination[at++] = T.CreateTruncating('.');
        // The fraction is below 10^digits: exactly that many digits, leading zeros included, so no count is needed.
        WriteDigitsOf(destination.Slice(at, digits), (ulong)fraction);
        return at + digits;
    }

    /// <summary>
    /// "000" to "999", each as four characters packed into one number (the fourth is 0), first digit in the low bits: written with
    /// one store instead of a copy of one to three characters.
    /// </summary>
    private static readonly ulong[] Triples = MakeTriples();

    /// <summary><see cref="Triples"/> as ASCII bytes: four packed into one number (the fourth is 0), first digit in the low bits.</summary>
    private static readonly uint[] ByteTriples = MakeByteTriples();

    /// <summary>How many of the three digits of each number below 1000 are left when its trailing zeros are dropped (0 for 0).</summary>
    private static readonly byte[] TrimmedDigits = MakeTrimmedDigits();

    private static ulong[] MakeTriples()
    {
        var triples = new ulong[1000];
        for (int n = 0; n < triples.Length; n++)
        {
            triples[n] = (ulong)(uint)('0' + n / 100) | (ulong)(uint)('0' + n / 10 % 10) << 16 | (ulong)(uint)('0' + n % 10) << 32;
        }
        return triples;
    }

    private static uint[] MakeByteTriples()
    {
        var triples = new uint[1000];
        for (int n = 0; n < triples.Length; n++)
        {
            triples[n] = (uint)('0' + n / 100) | (uint)('0' + n / 10 % 10) << 8 | (uint)('0' + n % 10) << 16;
        }
        return triples;
    }

    private static byte[] MakeTrimmedDigits()
    {
        var digits = new byte[1000];
        for (int n = 1; n < digits.Length; n++)
        {
            digits[n] = (byte)(n % 10 != 0 ? 3 : n % 100 != 0 ? 2 : 1);
        }
        return digits;
    }

    /// <summary>
    /// Stores the digits of <paramref name="triple"/> (below 1000, three digits with leading zeros) at <paramref name="at"/>, the first
    /// <paramref name="skipped"/> of them left out, as four packed characters or bytes (the place must hold four); returns
    /// <paramref name="at"/> + <paramref name="count"/>.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Put<T>(Span<T> destination, int at, uint triple, int skipped, int count)
        where T : unmanaged, IBinaryInteger<T>
    {
        Span<byte> place = System.Runtime.InteropServices.MemoryMarshal.AsBytes(destination.Slice(at, 4));
        if (typeof(T) == typeof(byte))
        {
            System.Runtime.InteropServices.MemoryMarshal.Write(place, ByteTriples[triple] >> (8 * skipped));
        }
        else
        {
            System.Runtime.InteropServices.MemoryMarshal.Write(place, Triples[triple] >> (16 * skipped));
        }
        return at + count;
    }

    /// <summary>Writes <paramref name="value"/> (below 1000) without leading zeros at <paramref name="at"/>; returns the position after it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int WriteBelowThousand<T>(Span<T> destination, int at, uint value)
        where T : unmanaged, IBinaryInteger<T>
    {
        int skipped = value >= 100 ? 0 : value >= 10 ? 1 : 2;
        return Put(destination, at, value, skipped, 3 - skipped);
    }

    /// <summary>
    /// Writes the fraction <c>.first second</c> (each group three digits, below 1000; <paramref name="second"/> 0 for three
    /// decimals) without its trailing zeros, nothing when it is 0; returns the position after it.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int WriteFraction<T>(Span<T> destination, int at, uint first, uint second)
        where T : unmanaged, IBinaryInteger<T>
    {
        if (second != 0)
        {
            destination[at] = T.CreateTruncating('.');
            at = Put(destination, at + 1, first, 0, 3);
            return Put(destination, at, second, 0, TrimmedDigits[second]);
        }
        if (first == 0)
        {
            return at;
        }
        destination[at] = T.CreateTruncating('.');
        return Put(destination, at + 1, first, 0, TrimmedDigits[first]);
    }

    /// <summary><paramref name="value"/> (not negative) divided by 10^<paramref name="decimals"/> (0–9), each case a division by a constant.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static long DivPow10(long value, int decimals) => (long)(decimals switch
    {
        0 => (ulong)value,
        1 => (ulong)value / 10,
        2 => (ulong)value / 100,
        3 => (ulong)value / 1_000,
        4 => (ulong)value / 10_000,
        5 => (ulong)value / 100_000,
        6 => (ulong)value / 1_000_000,
        7 => (ulong)value / 10_000_000,
        8 => (ulong)value / 100_000_000,
        9 => (ulong)value / 1_000_000_000,
        _ => throw new ArgumentOutOfRangeException(nameof(decimals)),
    });

    /// <summary>The digit pairs 00 to 99, for writing two digits per division.</summary>
    private const string DigitPairs =
        "00010203040506070809101112131415161718192021222324252627282930313233343536373839" +
        "4041424344454647484950515253545556575859606162636465666768697071727374757677787980" +
        "81828384858687888990919293949596979899";

    /// <summary>10^0 to 10^19: every power of ten an unsigned 64-bit number holds.</summary>
    private static readonly ulong[] Powers =
    [
        1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000, 100_000_000, 1_000_000_000, 10_000_000_000, 100_000_000_000,
        1_000_000_000_000, 10_000_000_000_000, 100_000_000_000_000, 1_000_000_000_000_000, 10_000_000_000_000_000,
        100_000_000_000_000_000, 1_000_000_000_000_000_000, 10_000_000_000_000_000_000,
    ];

    /// <summary>
    /// Writes a non-negative number with at least <paramref name="minDigits"/> digits (leading zeros); returns their count.
    /// The digits are counted from the highest bit (1233 / 4096 is just above log10 2, so the estimate is the count or one
    /// more, which one comparison decides).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static int WriteDigits<T>(Span<T> destination, long value, int minDigits)
        where T : unmanaged, IBinaryInteger<T>
    {
        ulong rest = (ulong)value;
        int estimate = (System.Numerics.BitOperations.Log2(rest | 1) + 1) * 1233 >> 12;
        int count = estimate + ((rest | 1) >= Powers[estimate] ? 1 : 0);
        count = Math.Max(count, minDigits);
        WriteDigitsOf(destination[..count], rest);
        return count;
    }

    /// <summary>Fills <paramref name="digits"/> with <paramref name="rest"/> (which fits), leading zeros first, two digits at a time from the last.</summary>
    /// <remarks>
    /// Optimised from its first call: unoptimised (tier-0) code calls out for every <c>T.CreateTruncating</c>, and a cold compile
    /// (the 400k job, the JIT tool) ran it so for most of its numbers.
    /// </remarks>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private static void WriteDigitsOf<T>(Span<T> digits, ulong rest)
        where T : unmanaged, IBinaryInteger<T>
    {
        int at = digits.Length;
        if (rest <= uint.MaxValue)
        {
            // Most numbers of a program fit 32 bits, whose divisions are cheaper.
            uint small = (uint)rest;
            while (small >= 100)
            {
                uint next = small / 100;
                int pair = (int)(small - next * 100) * 2;
                digits[--at] = T.CreateTruncating(DigitPairs[pair + 1]);
                digits[--at] = T.CreateTruncating(DigitPairs[pair]);
                small = next;
            }
            rest = small;
        }
        while (rest >= 100)
        {
            ulong next = rest / 100;
            int pair = (int)(rest - next * 100) * 2;
            digits[--at] = T.CreateTruncating(DigitPairs[pair + 1]);
            digits[--at] = T.CreateTruncating(DigitPairs[pair]);
            rest = next;
        }
        if (rest >= 10)
        {
            int pair = (int)rest * 2;
            digits[--at] = T.CreateTruncating(DigitPairs[pair + 1]);
            digits[--at] = T.CreateTruncating(DigitPairs[pair]);
        }
        else
        {
            digits[--at] = T.CreateTruncating('0' + (int)rest);
        }
        if (at > 0)
        {
            digits[..at].Fill(T.CreateTruncating('0'));
        }
    }

    /// <summary>1.5 · 2^52: any double of size below 2^51 plus this lies where doubles are the whole numbers.</summary>
    private const double RoundingShift = 6755399441055744.0;

    /// <summary>
    /// <paramref name="value"/> rounded to a whole number, halves to even, as <see cref="Math.Round(double)"/> (which the native
    /// build calls as a function) for every value of size below 2^51 (about 2.25·10^15), except that −0.4 gives 0, not −0.
    /// Larger values, infinities and NaN give a number of size 2^51 − 1 or more, or NaN: callers check for 10^15 and fall back.
    /// </summary>
    /// <remarks>The processor rounds the sum to the nearest double, ties to even, and there the doubles are whole numbers.</remarks>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal static double RoundEven(double value) => value + RoundingShift - RoundingShift;

    /// <summary>
    /// Writes exactly the text of <see cref="Num.F(double, int)"/> (which switches to E notation below 0.0001) into
    /// <paramref name="destination"/> (at least <see cref="MaxChars"/> long) and returns the number of characters.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int WriteF(Span<char> destination, double value, int decimals)
    {
        int written = TryWriteF(destination, value, decimals);
        if (written >= 0)
        {
            return written;
        }
        Num.Clean(Math.Round(value, decimals)).TryFormat(destination, out int general, "G15", Num.Inv);
        return general;
    }

    /// <summary>
    /// Writes the ASCII bytes of what <see cref="WriteF"/> writes as characters and returns their count, or −1 where it writes
    /// .NET's general text (E notation, huge values: the caller writes those as characters).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal static int TryWriteFAscii(Span<byte> destination, double value, int decimals) => TryWriteF(destination, value, decimals);

    /// <summary><see cref="WriteF"/>'s fast digits, or −1 where it takes .NET's general text.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int TryWriteF<T>(Span<T> destination, double value, int decimals)
        where T : unmanaged, IBinaryInteger<T>
    {
        // G15 writes fixed notation down to 0.0001 and E notation below it (1E-05): only the general path writes that.
        if ((uint)decimals <= MaxDecimals && TryScale(value, decimals, out double rounded)
            && (decimals <= 4 || rounded == 0 || Math.Abs(rounded) >= Pow10[decimals - 4]))
        {
            // What TryWriteScaled writes, with the scaled value already at hand.
            return WriteDecimal(destination, rounded < 0, (long)Math.Abs(rounded), decimals);
        }
        return -1;
    }
}

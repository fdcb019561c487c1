using System.Globalization;
using System.Text;

namespace Machina;

/// <summary>Reads one message from the RAPID driver: an acknowledgement <c>@id code</c> or a data message <c>$code v1 … vn</c>.</summary>
internal static class AbbDriverMessage
{
    /// <summary>Most values a data message may carry.</summary>
    internal const int MaxValues = 32;

    /// <summary>Values at or above this mean "axis not in use" in RAPID (9E9).</summary>
    internal const double UnusedAxisThreshold = 9e9;

    /// <summary>Reads the id of an acknowledgement <c>@id …</c>; false when the id is not a whole number.</summary>
    internal static bool TryReadAcknowledgement(ReadOnlySpan<byte> message, out int id)
    {
        ReadOnlySpan<byte> token = FirstToken(message[1..]);
        return int.TryParse(token, NumberStyles.None, CultureInfo.InvariantCulture, out id) ||
               TryReadWholeDouble(token, out id);
    }

    /// <summary>Reads a data message <c>$code v1 … vn</c> into <paramref name="values"/>; false when a token is not a number.</summary>
    internal static bool TryReadData(ReadOnlySpan<byte> message, out int code, Span<double> values, out int count)
    {
        count = 0;
        code = 0;
        ReadOnlySpan<byte> rest = message[1..];
        ReadOnlySpan<byte> token = FirstToken(rest);
        if (!int.TryParse(token, NumberStyles.None, CultureInfo.InvariantCulture, out code))
        {
            return false;
        }
        rest = rest[token.Length..];
        while (true)
        {
            rest = rest.TrimStart((byte)' ');
            if (rest.IsEmpty)
            {
                return true;
            }
            token = FirstToken(rest);
            if (count == values.Length ||
                !double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out values[count]))
            {
                return false;
            }
            count++;
            rest = rest[token.Length..];
        }
    }

    /// <summary>A RAPID external axis value, or null when it is 9E9 (not in use).</summary>
    internal static double? Axis(double value) => value >= UnusedAxisThreshold ? null : value;

    /// <summary>External axes from six values, or null when none is in use.</summary>
    internal static ExternalAxes? Axes(ReadOnlySpan<double> v)
    {
        var axes = new ExternalAxes(Axis(v[0]), Axis(v[1]), Axis(v[2]), Axis(v[3]), Axis(v[4]), Axis(v[5]));
        return axes.IsEmpty ? null : axes;
    }

    /// <summary>The message as text for error reports.</summary>
    internal static string Text(ReadOnlySpan<byte> message) => Encoding.UTF8.GetString(message);

    private static ReadOnlySpan<byte> FirstToken(ReadOnlySpan<byte> text)
    {
        int end = text.IndexOf((byte)' ');
        return end < 0 ? text : text[..end];
    }

    // RAPID may print an id as "12" or, from a num, "12.0"; both are accepted when whole.
    private static bool TryReadWholeDouble(ReadOnlySpan<byte> token, out int id)
    {
        id = 0;
        if (!double.TryParse(token, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) ||
            value != Math.Floor(value) || value < 0 || value > int.MaxValue)
        {
            return false;
        }
        id = (int)value;
        return true;
    }
}

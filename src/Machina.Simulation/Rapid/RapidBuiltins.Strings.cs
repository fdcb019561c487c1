using System.Globalization;

namespace Machina.Simulation.Rapid;

/// <summary>String functions: StrLen, StrPart, StrFind, StrMatch, StrToVal, NumToStr, ValToStr.</summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Strings() =>
    [
        Function("StrLen", "num", [P("Str", "string")], call => RapidBoxes.Num(call.Str(0).Length)),
        StrPart,
        Function("StrFind", "num", [P("Str", "string"), P("ChPos", "num"), P("Set", "string"), Sw("NotInSet")], call =>
        {
            string s = call.Str(0), set = call.Str(2);
            int start = StartOf(call, s, call.Num(1));
            bool notIn = call.Has(3);
            ReadOnlySpan<char> rest = s.AsSpan(start);
            int found = notIn ? rest.IndexOfAnyExcept(set) : rest.IndexOfAny(set);
            return RapidBoxes.Num(found < 0 ? s.Length + 1 : start + found + 1); // a shared box for a position: no allocation per call
        }),
        Function("StrMatch", "num", [P("Str", "string"), P("ChPos", "num"), P("Pattern", "string")], call =>
        {
            string s = call.Str(0);
            int found = s.IndexOf(call.Str(2), StartOf(call, s, call.Num(1)), StringComparison.Ordinal);
            return RapidBoxes.Num(found < 0 ? s.Length + 1 : found + 1);
        }),
        Function("StrToVal", "bool", [P("Str", "string"), P("Val", null, true)], call =>
        {
            ReadOnlySpan<char> text = call.Text(0).Trim();
            RapidDataType? type = call.TypeOf(1);
            if (type is { Rank: 0, Element.IsNumeric: true })
            {
                if (!(RapidNumberText.TryParsePlain(text, out double value)
                    || double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out value)) || !double.IsFinite(value))
                {
                    return RapidBoxes.Bool(false);
                }
                call.Set(1, RapidBoxes.Num(value));
                return RapidBoxes.Bool(true);
            }
            if (type is { Rank: 0, Element.Kind: RapidTypeKind.Bool })
            {
                bool isTrue = text.Equals("TRUE", StringComparison.OrdinalIgnoreCase);
                if (!isTrue && !text.Equals("FALSE", StringComparison.OrdinalIgnoreCase))
                {
                    return RapidBoxes.Bool(false);
                }
                call.Set(1, RapidBoxes.Bool(isTrue));
                return RapidBoxes.Bool(true);
            }
            if (type is not { } data || (data.Rank == 0 && data.Element.Kind == RapidTypeKind.Opaque))
            {
                throw ArgumentError(call, $"StrToVal: {type} is not a value data type");
            }
            if (ReadLiteral(text, data, call.Value(1)) is not { } literal)
            {
                return RapidBoxes.Bool(false); // the data are unchanged
            }
            call.Set(1, literal);
            return RapidBoxes.Bool(true);
        }),
        Function("NumToStr", "string", [P("Val", "num"), P("Dec", "num"), Sw("Exp")], call =>
        {
            double value = call.Num(0), dec = call.Num(1);
            if (dec < 0 || dec > 15 || dec != Math.Floor(dec))
            {
                throw ArgumentError(call, $"NumToStr: {RapidValues.FormatNumber(dec)} is not a number of decimals");
            }
            return call.Has(2)
                ? value.ToString("0." + new string('0', (int)dec) + "E+00", CultureInfo.InvariantCulture)
                : NumberText(value, (int)dec);
        }),
        Function("ValToStr", "string", [P("Val", null)], call => RapidValues.ToText(call.Value(0))),
    ];

    /// <summary>StrPart: the part of a string from a character position, of a length (made with <see cref="All"/>, which holds it).</summary>
    internal static RapidBuiltin StrPart => StrPartBuiltin.Instance;

    /// <summary>
    /// Holds StrPart's built-in: a class of its own, whose one field is made when first read, so that it is there whichever of this
    /// partial class's static initialisers runs first.
    /// </summary>
    private static class StrPartBuiltin
    {
        /// <summary>The built-in.</summary>
        public static readonly RapidBuiltin Instance = Function("StrPart", "string", [P("Str", "string"), P("ChPos", "num"), P("Len", "num")], call =>
        {
            (string s, int start, int length) = Part(call);
            return length == 1 ? RapidBoxes.Char(s[start]) : s.Substring(start, length);
        });
    }

    /// <summary>
    /// The string a StrPart call's arguments name, and the start (from 0) and length of its part, with StrPart's error when the part is
    /// not inside the string: the part itself is made only by whoever needs a string (<see cref="RapidCall.Text"/> reads it in place).
    /// </summary>
    internal static (string Text, int Start, int Length) Part(RapidCall call)
    {
        string s = call.Str(0);
        double pos = call.Num(1), len = call.Num(2);
        if (pos < 1 || len < 0 || pos + len - 1 > s.Length || pos != Math.Floor(pos) || len != Math.Floor(len))
        {
            throw ArgumentError(call, $"StrPart: characters {RapidValues.FormatNumber(pos)} to {RapidValues.FormatNumber(pos + len - 1)} are outside the string of length {s.Length}");
        }
        return (s, (int)pos - 1, (int)len);
    }

    /// <summary>A number rounded to <paramref name="decimals"/> decimals, without trailing zeros (NumToStr).</summary>
    internal static string NumberText(double value, int decimals)
    {
        double rounded = Math.Round(value, decimals, MidpointRounding.AwayFromZero);
        if (decimals == 0 && Math.Abs(rounded) < 1e15)
        {
            return ((long)rounded).ToString(CultureInfo.InvariantCulture); // ids and codes ("F0" with no point to trim; -0 is 0)
        }
        string text = rounded.ToString("F" + decimals, CultureInfo.InvariantCulture);
        if (text.Contains('.', StringComparison.Ordinal))
        {
            text = text.TrimEnd('0').TrimEnd('.');
        }
        return text == "-0" ? "0" : text;
    }

    private static int StartOf(RapidCall call, string s, double position) =>
        position >= 1 && position <= s.Length + 1 && position == Math.Floor(position)
            ? (int)position - 1
            : throw ArgumentError(call, $"the character position {RapidValues.FormatNumber(position)} is outside the string of length {s.Length}");

    private static IEnumerable<RapidBuiltin> MathFunctions() =>
    [
        Function("Abs", "num", [P("Input", "num")], call => Math.Abs(call.Num(0))),
        Function("Sqrt", "num", [P("Value", "num")], call => call.Num(0) >= 0 ? Math.Sqrt(call.Num(0)) : throw ArgumentError(call, "Sqrt: the value is negative")),
        Function("Sin", "num", [P("Angle", "num")], call => Math.Sin(call.Num(0) * Math.PI / 180)),
        Function("Cos", "num", [P("Angle", "num")], call => Math.Cos(call.Num(0) * Math.PI / 180)),
        Function("Tan", "num", [P("Angle", "num")], call => Math.Tan(call.Num(0) * Math.PI / 180)),
        Function("ASin", "num", [P("Value", "num")], call => Math.Asin(call.Num(0)) * 180 / Math.PI),
        Function("ACos", "num", [P("Value", "num")], call => Math.Acos(call.Num(0)) * 180 / Math.PI),
        Function("ATan", "num", [P("Value", "num")], call => Math.Atan(call.Num(0)) * 180 / Math.PI),
        Function("ATan2", "num", [P("Y", "num"), P("X", "num")], call => Math.Atan2(call.Num(0), call.Num(1)) * 180 / Math.PI),
        Function("Exp", "num", [P("Exponent", "num")], call => Math.Exp(call.Num(0))),
        Function("Pow", "num", [P("Base", "num"), P("Exponent", "num")], call => Math.Pow(call.Num(0), call.Num(1))),
        Function("Round", "num", [P("Val", "num"), Opt("Dec", "num")], call => Math.Round(call.Num(0), call.Has(1) ? (int)call.Num(1) : 0, MidpointRounding.AwayFromZero)),
        Function("Trunc", "num", [P("Val", "num"), Opt("Dec", "num")], call =>
        {
            double scale = Math.Pow(10, call.Has(1) ? (int)call.Num(1) : 0);
            return Math.Truncate(call.Num(0) * scale) / scale;
        }),
        Function("VectMagn", "num", [P("Vector", "pos")], call => RapidGeometry.ToVector(call.Record(0)).Length),
    ];
}

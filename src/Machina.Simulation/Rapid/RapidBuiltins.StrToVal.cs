using System.Globalization;

namespace Machina.Simulation.Rapid;

/// <summary>
/// StrToVal into a record, an array or a string: the text is a RAPID literal of the data's type (<c>"[600, 500, 225.3]"</c> for a pos,
/// <c>"[0,1,2,3,4,5,6,7,8,9]"</c> for a <c>num{10}</c>, <c>"""abc"""</c> for a string). The Reference Manual's StrToVal: Val is "of any
/// value data type", "atomic, record, record component, array or array element", and the data are unchanged when the conversion fails
/// (the function then returns FALSE). An aggregate must have exactly the components (elements) of the data.
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>
    /// Reads <paramref name="text"/> as a literal of <paramref name="type"/>, shaped as <paramref name="current"/> (an array's
    /// dimensions are the data's); null when the text is not such a literal.
    /// </summary>
    internal static object? ReadLiteral(ReadOnlySpan<char> text, RapidDataType type, object current)
    {
        int at = 0;
        object? value = ReadValue(text, ref at, type, current);
        SkipBlanks(text, ref at);
        return at == text.Length ? value : null;
    }

    private static object? ReadValue(ReadOnlySpan<char> text, ref int at, RapidDataType type, object current)
    {
        SkipBlanks(text, ref at);
        if (type.Rank > 0)
        {
            if (current is not RapidArray shape)
            {
                return null;
            }
            var items = new object[shape.Items.Length];
            return ReadDimension(text, ref at, type.Element, shape, 0, 0, items) ? new RapidArray(shape.Dimensions, items) : null;
        }
        RapidType element = type.Element;
        switch (element.Kind)
        {
            case RapidTypeKind.Num or RapidTypeKind.Dnum:
                return ReadNumber(text, ref at);
            case RapidTypeKind.Bool:
                return ReadWord(text, ref at, "TRUE") ? RapidBoxes.Bool(true) : ReadWord(text, ref at, "FALSE") ? RapidBoxes.Bool(false) : null;
            case RapidTypeKind.String:
                return RapidLexer.StringLiteral(text, ref at);
            case RapidTypeKind.Record:
                var fields = new object[element.Fields.Count];
                if (!ReadChar(text, ref at, '['))
                {
                    return null;
                }
                for (int i = 0; i < fields.Length; i++)
                {
                    RapidDataType fieldType = element.Fields[i].Type;
                    object shape = (current as RapidRecord)?.Fields[i] ?? RapidValues.Default(fieldType);
                    if ((i > 0 && !ReadChar(text, ref at, ',')) || ReadValue(text, ref at, fieldType, shape) is not { } field)
                    {
                        return null;
                    }
                    fields[i] = field;
                }
                return ReadChar(text, ref at, ']') ? new RapidRecord(element, fields) : null;
            default:
                return null; // a non-value type has no literal
        }
    }

    /// <summary>The elements of one dimension from element <paramref name="offset"/> on: <c>[a, b, …]</c>, nested per dimension (row by row).</summary>
    private static bool ReadDimension(ReadOnlySpan<char> text, ref int at, RapidType element, RapidArray shape, int dimension, int offset, object[] into)
    {
        int[] dims = shape.Dimensions;
        int stride = 1;
        for (int d = dimension + 1; d < dims.Length; d++)
        {
            stride *= dims[d];
        }
        if (!ReadChar(text, ref at, '['))
        {
            return false;
        }
        for (int i = 0; i < dims[dimension]; i++)
        {
            int index = offset + i * stride;
            if (i > 0 && !ReadChar(text, ref at, ','))
            {
                return false;
            }
            if (dimension + 1 < dims.Length)
            {
                if (!ReadDimension(text, ref at, element, shape, dimension + 1, index, into))
                {
                    return false;
                }
            }
            else if (ReadValue(text, ref at, new RapidDataType(element), shape.Items[index]) is { } item)
            {
                into[index] = item;
            }
            else
            {
                return false;
            }
        }
        return ReadChar(text, ref at, ']');
    }

    /// <summary>A number literal (digits, a point, an exponent), as a box; null when there is none or it is not finite.</summary>
    private static object? ReadNumber(ReadOnlySpan<char> text, ref int at)
    {
        int start = at;
        while (at < text.Length && (char.IsAsciiDigit(text[at]) || text[at] is '.' or '+' or '-' or 'e' or 'E'))
        {
            at++;
        }
        return double.TryParse(text[start..at], NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && double.IsFinite(value)
            ? RapidBoxes.Num(value)
            : null;
    }

    private static bool ReadWord(ReadOnlySpan<char> text, ref int at, string word)
    {
        if (text.Length - at < word.Length || !text.Slice(at, word.Length).Equals(word, StringComparison.OrdinalIgnoreCase)
            || (at + word.Length < text.Length && char.IsAsciiLetterOrDigit(text[at + word.Length])))
        {
            return false;
        }
        at += word.Length;
        return true;
    }

    private static bool ReadChar(ReadOnlySpan<char> text, ref int at, char c)
    {
        SkipBlanks(text, ref at);
        if (at >= text.Length || text[at] != c)
        {
            return false;
        }
        at++;
        return true;
    }

    private static void SkipBlanks(ReadOnlySpan<char> text, ref int at)
    {
        while (at < text.Length && char.IsWhiteSpace(text[at]))
        {
            at++;
        }
    }
}

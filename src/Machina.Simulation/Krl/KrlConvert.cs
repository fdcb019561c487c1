using System.Runtime.CompilerServices;

namespace Machina.Simulation.Krl;

/// <summary>Assignment conversions of KRL: INT and REAL into each other, structures component by component, strings into CHAR arrays.</summary>
internal static class KrlConvert
{
    /// <summary><paramref name="value"/> as a value of <paramref name="type"/>; <paramref name="old"/> gives the components an aggregate leaves out.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static object To(KrlType type, object value, object? old)
    {
        // The usual store (an INT into an INT, a REAL into a REAL: most of the driver's, several dozen an action) inlines.
        KrlKind kind = type.Kind;
        return (kind == KrlKind.Real && value is double) || (kind == KrlKind.Int && value is int) ? value : Converted(type, value, old);
    }

    /// <summary>The rest of <see cref="To"/>: a conversion, a copy or a structure filled in.</summary>
    private static object Converted(KrlType type, object value, object? old)
    {
        switch (type.Kind)
        {
            case KrlKind.Int:
                return value is int ? value : KrlValues.Box(KrlValues.ToInt(value));
            case KrlKind.Real:
                return value is double ? value : KrlValues.ToReal(value);
            case KrlKind.Char when value is string one:
                return KrlValues.Box(one[0]);
            case KrlKind.Char when value is int code:
                return code is >= 0 and <= 255
                    ? KrlValues.Box((char)code)
                    : throw new KrlRuntimeException($"Value assignment inadmissible: a CHAR takes a character code from 0 to 255, not {code}");
            case KrlKind.Struct when value is KrlStructValue s:
            {
                if (s.Type == type)
                {
                    return s.Copy();
                }
                var result = old is KrlStructValue o && o.Type == type ? o.Copy() : (KrlStructValue)KrlValues.Default(type);
                int[] map = type.FieldsFrom(s.Type);
                for (int i = 0; i < map.Length; i++)
                {
                    int j = map[i];
                    if (j >= 0)
                    {
                        KrlType field = type.Fields[j].Type;
                        if (field.Kind == KrlKind.Real && s.Type.Fields[i].Type.Kind is KrlKind.Real or KrlKind.Int)
                        {
                            result.SetReal(j, s.Real(i)); // a FRAME's X into an E6POS's: no box between the two structures' numbers
                        }
                        else
                        {
                            result.Values[j] = To(field, s.Values[i], Old(field, result, j));
                        }
                        result.Unset = s.IsGiven(i) ? result.Unset & ~(1 << j) : result.Unset | (1 << j);
                    }
                }
                return result;
            }
            case KrlKind.Struct when value is KrlPartialValue p:
            {
                var result = old is KrlStructValue o && o.Type == type ? o.Copy() : (KrlStructValue)KrlValues.Default(type);
                for (int i = 0; i < p.Indexes.Length; i++)
                {
                    int j = p.Type == type ? p.Indexes[i] : type.FieldsFrom(p.Type)[p.Indexes[i]];
                    if (j >= 0)
                    {
                        KrlType field = type.Fields[j].Type;
                        result.Values[j] = To(field, p.Values[i], Old(field, result, j));
                        result.Give(j);
                    }
                }
                return result;
            }
            case KrlKind.Array when value is string text:
            {
                var array = (KrlArrayValue)KrlValues.Default(type);
                KrlValues.SetText(array.Objects, 0, array.Length, text);
                return array;
            }
            case KrlKind.Array when value is KrlArrayValue a:
            {
                var array = (KrlArrayValue)KrlValues.Default(type);
                array.CopyFrom(a, Math.Min(a.Length, array.Length));
                return array;
            }
            default:
                return KrlValues.Copy(value);
        }
    }

    /// <summary>The value component <paramref name="j"/> of <paramref name="structure"/> has before a store, where the store needs it (a structure, which an aggregate fills in); null otherwise (a REAL's read would box it).</summary>
    private static object? Old(KrlType field, KrlStructValue structure, int j) => field.Kind == KrlKind.Struct ? structure.Values[j] : null;
}

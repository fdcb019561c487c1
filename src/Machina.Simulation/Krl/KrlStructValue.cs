using System.Runtime.CompilerServices;

namespace Machina.Simulation.Krl;

/// <summary>
/// A structure value: its type and one value per component, read and written through this value's indexer (<c>s[i]</c>, or
/// <c>s.Values[i]</c>) or, for a REAL, through <see cref="Real"/> and <see cref="SetReal"/>. A structure whose components are
/// all INT, REAL, BOOL or CHAR (FRAME, POS, E6POS, AXIS, E6AXIS, EKI_STATUS, $VEL, $APO, ...) holds them unboxed, as doubles
/// (an INT, a BOOL as 0 or 1 and a CHAR's code are exact in a double): a REAL stored there allocates nothing and a copy is one
/// block move. Other structures hold their components as objects.
/// </summary>
internal sealed class KrlStructValue
{
    /// <summary>
    /// The components: a <c>double[]</c> for a structure of INT, REAL, BOOL and CHAR components (<see cref="_numbers"/>), else an
    /// <c>object[]</c>. One field and a flag, not two arrays' fields: the driver makes several structures an action and each field is
    /// 8 bytes of every one.
    /// </summary>
    private readonly object _store;

    /// <summary>True when <see cref="_store"/> is a <c>double[]</c>.</summary>
    private readonly bool _numbers;

    /// <summary>A structure of <paramref name="type"/> with the components <paramref name="values"/> (in the type's order).</summary>
    public KrlStructValue(KrlType type, object[] values)
    {
        Type = type;
        if (NumberKinds(type) is { } kinds)
        {
            var numbers = new double[values.Length];
            for (int i = 0; i < values.Length; i++)
            {
                numbers[i] = Number(kinds[i], values[i]);
            }
            _store = numbers;
            _numbers = true;
        }
        else
        {
            _store = values;
        }
    }

    private KrlStructValue(KrlType type, double[] numbers)
    {
        Type = type;
        _store = numbers;
        _numbers = true;
    }

    /// <summary>The components as numbers (only when <see cref="_numbers"/>).</summary>
    private double[] Numbers => Unsafe.As<double[]>(_store);

    /// <summary>The components as objects (only when not <see cref="_numbers"/>).</summary>
    private object[] Objects => Unsafe.As<object[]>(_store);

    /// <summary>The components' kinds of a structure of numbers (its type's, found when its first value was made).</summary>
    private KrlKind[] Kinds => Type.NumberKinds!;

    /// <summary>True when the components are held as numbers (every one an INT, REAL, BOOL or CHAR): the value holds no other value.</summary>
    public bool HoldsNumbers => _numbers;

    /// <summary>The structure type.</summary>
    public KrlType Type { get; }

    /// <summary>The components: this value itself, whose indexer reads and writes them (kept so that <c>s.Values[i]</c> reads as before).</summary>
    public KrlStructValue Values => this;

    /// <summary>The number of components.</summary>
    public int Length => _numbers ? Numbers.Length : Objects.Length;

    /// <summary>Component <paramref name="index"/> as an object (a REAL read this way is boxed: <see cref="Real"/> reads it without).</summary>
    public object this[int index]
    {
        get => _numbers ? Boxed(Kinds[index], Numbers[index]) : Objects[index];
        set
        {
            if (_numbers)
            {
                Numbers[index] = Number(Kinds[index], value);
            }
            else
            {
                Objects[index] = value;
            }
        }
    }

    /// <summary>The INT or REAL component <paramref name="index"/> as a REAL, without a box.</summary>
    public double Real(int index) => _numbers ? Numbers[index] : KrlValues.ToReal(Objects[index]);

    /// <summary>Stores the REAL <paramref name="value"/> in the REAL component <paramref name="index"/>, without a box when the structure holds numbers.</summary>
    public void SetReal(int index, double value)
    {
        if (_numbers && Kinds[index] == KrlKind.Real)
        {
            Numbers[index] = value;
        }
        else
        {
            this[index] = value;
        }
    }

    /// <summary>
    /// The components that were never given a value (bit i: component i), tracked for the status S and turn T of a POS or E6POS
    /// only: a PTP to a position whose S and T were never given takes the solution nearest the current axes, as the controller
    /// does. Reading such a component gives 0.
    /// </summary>
    public int Unset { get; set; }

    /// <summary>
    /// True for a value the controller keeps and hands out again (an EthernetKRL status: see <c>KrlTwinController.Status</c>), which
    /// several variables may hold at once: it is never written, a write of one of its components copies it first.
    /// </summary>
    public bool Shared { get; init; }

    /// <summary>A deep copy (KRL structures are values); the copy is the holder's own.</summary>
    public KrlStructValue Copy()
    {
        if (_numbers)
        {
            double[] numbers = Numbers;
            var copy = new double[numbers.Length];
            numbers.AsSpan().CopyTo(copy);
            return new KrlStructValue(Type, copy) { Unset = Unset };
        }
        object[] objects = Objects;
        var values = new object[objects.Length];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = KrlValues.Copy(objects[i]);
        }
        return new KrlStructValue(Type, values) { Unset = Unset };
    }

    /// <summary>The initial value of a structure of <paramref name="type"/> when its components are all INT, REAL, BOOL or CHAR (all 0: 0, 0.0, FALSE, the unset CHAR), else null.</summary>
    public static KrlStructValue? Zero(KrlType type) =>
        NumberKinds(type) is { } kinds ? new KrlStructValue(type, new double[kinds.Length]) { Unset = KrlTypes.StatusTurnBits(type) } : null;

    /// <summary>True when component <paramref name="index"/> was given a value.</summary>
    public bool IsGiven(int index) => (Unset & (1 << index)) == 0;

    /// <summary>Marks component <paramref name="index"/> as given a value.</summary>
    public void Give(int index) => Unset &= ~(1 << index);

    /// <summary>The REAL (or INT) component <paramref name="field"/>, 0 when the type has none.</summary>
    public double Number(string field) => Type.FieldIndex(field) is int i and >= 0 ? Real(i) : 0;

    /// <summary>The kinds of a structure type's components when each is an INT, REAL, BOOL or CHAR, else null (found once per type).</summary>
    private static KrlKind[]? NumberKinds(KrlType type)
    {
        KrlKind[]? kinds = type.NumberKinds;
        if (kinds is null)
        {
            kinds = [.. type.Fields.Select(f => f.Type.Kind)];
            if (!kinds.All(k => k is KrlKind.Int or KrlKind.Real or KrlKind.Bool or KrlKind.Char))
            {
                kinds = [];
            }
            type.NumberKinds = kinds;
        }
        return kinds.Length == 0 && type.Fields.Count > 0 ? null : kinds;
    }

    /// <summary>A component's value as the double it is held as.</summary>
    private static double Number(KrlKind kind, object value) => kind switch
    {
        KrlKind.Real => KrlValues.ToReal(value),
        KrlKind.Int => KrlValues.ToInt(value),
        KrlKind.Bool => (bool)value ? 1 : 0,
        _ => (char)value,
    };

    /// <summary>A held double as the component's value (INT, BOOL and CHAR from their shared boxes).</summary>
    private static object Boxed(KrlKind kind, double number) => kind switch
    {
        KrlKind.Real => number,
        KrlKind.Int => KrlValues.Box((int)number),
        KrlKind.Bool => KrlValues.Box(number != 0),
        _ => KrlValues.Box((char)number),
    };
}

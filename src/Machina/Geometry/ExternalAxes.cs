namespace Machina;

/// <summary>
/// Values of up to six external axes (tracks, positioners): millimetres for linear axes, degrees for rotary ones.
/// An axis without a value is <c>null</c>. <c>default</c> has every axis unset.
/// </summary>
public readonly struct ExternalAxes : IEquatable<ExternalAxes>
{
    /// <summary>Number of external axes Machina tracks.</summary>
    public const int Count = 6;

    private readonly double? _a1, _a2, _a3, _a4, _a5, _a6;

    /// <summary>External axes from up to six values; null (or ABB's 9E9 "no axis" marker, 9 000 000 000 and above) leaves an axis unset.</summary>
    public ExternalAxes(double? a1 = null, double? a2 = null, double? a3 = null, double? a4 = null, double? a5 = null, double? a6 = null)
    {
        _a1 = Filter(a1); _a2 = Filter(a2); _a3 = Filter(a3); _a4 = Filter(a4); _a5 = Filter(a5); _a6 = Filter(a6);
    }

    /// <summary>ABB's "no axis" marker: values from 9 000 000 000 up mean that the axis is unset.</summary>
    internal const double Unset = 9e9;

    private static double? Filter(double? v)
    {
        if (v is null || v.Value >= Unset)
        {
            return null;
        }
        return Num.Finite(v.Value, "external axis value");
    }

    /// <summary>All axes unset.</summary>
    public static ExternalAxes None => default;

    /// <summary>
    /// Value of axis 1..6 (one-based, as robot languages count them), or null when unset. Use <see cref="Axis"/> (also one-based)
    /// or <see cref="ToArray"/> (zero-based).
    /// </summary>
    public double? Axis(int axisNumber) => this[axisNumber];

    /// <summary>Value of external axis 1, or null when unset (the original's name).</summary>
    public double? EA1 => _a1;

    /// <summary>Value of external axis 2, or null when unset.</summary>
    public double? EA2 => _a2;

    /// <summary>Value of external axis 3, or null when unset.</summary>
    public double? EA3 => _a3;

    /// <summary>Value of external axis 4, or null when unset.</summary>
    public double? EA4 => _a4;

    /// <summary>Value of external axis 5, or null when unset.</summary>
    public double? EA5 => _a5;

    /// <summary>Value of external axis 6, or null when unset.</summary>
    public double? EA6 => _a6;

    /// <summary>Number of external axes (6), the original's name for <see cref="Count"/>.</summary>
    public int Length => Count;

    /// <summary>
    /// Value of axis 1..6 (one-based), or null when unset. Internal on purpose: the original's public indexer counted from 0, so
    /// <c>axes[0]</c> ported from it must not compile against this one; users call <see cref="Axis"/>.
    /// </summary>
    internal double? this[int axisNumber] => axisNumber switch
    {
        1 => _a1, 2 => _a2, 3 => _a3, 4 => _a4, 5 => _a5, 6 => _a6,
        _ => throw new ArgumentOutOfRangeException(nameof(axisNumber), axisNumber, "External axis numbers are 1 to 6."),
    };

    /// <summary>True when no axis has a value.</summary>
    public bool IsEmpty => _a1 is null && _a2 is null && _a3 is null && _a4 is null && _a5 is null && _a6 is null;

    /// <summary>A copy with axis <paramref name="axisNumber"/> (1..6) set to <paramref name="value"/>.</summary>
    public ExternalAxes With(int axisNumber, double? value)
    {
        double?[] v = ToArray();
        if (axisNumber < 1 || axisNumber > Count)
        {
            throw new ArgumentOutOfRangeException(nameof(axisNumber), axisNumber, "External axis numbers are 1 to 6.");
        }
        v[axisNumber - 1] = value;
        return new ExternalAxes(v[0], v[1], v[2], v[3], v[4], v[5]);
    }

    /// <summary>The six values (index 0 is axis 1) as a new array.</summary>
    public double?[] ToArray() => [_a1, _a2, _a3, _a4, _a5, _a6];

    /// <summary>Exact equality.</summary>
    public bool Equals(ExternalAxes other) =>
        _a1 == other._a1 && _a2 == other._a2 && _a3 == other._a3 && _a4 == other._a4 && _a5 == other._a5 && _a6 == other._a6;

    /// <inheritdoc/>
    public override bool Equals(object? obj) => obj is ExternalAxes e && Equals(e);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(_a1, _a2, _a3, _a4, _a5, _a6);

    /// <summary>Exact equality.</summary>
    public static bool operator ==(ExternalAxes a, ExternalAxes b) => a.Equals(b);

    /// <summary>Exact inequality.</summary>
    public static bool operator !=(ExternalAxes a, ExternalAxes b) => !a.Equals(b);

    /// <summary>Text such as <c>[100, null, null, null, null, null]</c> (3 decimals).</summary>
    public override string ToString() => "[" + string.Join(", ", ToArray().Select(v => v is null ? "null" : Num.F(v.Value, 3))) + "]";
}

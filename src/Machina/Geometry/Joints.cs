namespace Machina;

/// <summary>The six joint (axis) angles of a robot arm, in degrees. Every value is valid; <c>default</c> is all zeros.</summary>
/// <param name="J1">Axis 1 (base), degrees.</param>
/// <param name="J2">Axis 2 (shoulder), degrees.</param>
/// <param name="J3">Axis 3 (elbow), degrees.</param>
/// <param name="J4">Axis 4 (wrist 1), degrees.</param>
/// <param name="J5">Axis 5 (wrist 2), degrees.</param>
/// <param name="J6">Axis 6 (wrist 3 / flange), degrees.</param>
public readonly record struct Joints(double J1, double J2, double J3, double J4, double J5, double J6)
{
    /// <summary>Number of joints.</summary>
    public const int Count = 6;

    /// <summary>Joint value by zero-based index 0..5.</summary>
    public double this[int index] => index switch
    {
        0 => J1, 1 => J2, 2 => J3, 3 => J4, 4 => J5, 5 => J6,
        _ => throw new ArgumentOutOfRangeException(nameof(index), index, "Joint index must be 0 to 5."),
    };

    /// <summary>Joints from six values.</summary>
    public static Joints FromArray(ReadOnlySpan<double> values)
    {
        if (values.Length != Count)
        {
            throw new ArgumentException($"Joints need exactly 6 values, got {values.Length}.", nameof(values));
        }
        return new Joints(values[0], values[1], values[2], values[3], values[4], values[5]);
    }

    /// <summary>The six values as a new array.</summary>
    public double[] ToArray() => [J1, J2, J3, J4, J5, J6];

    /// <summary>True when every value is a finite number.</summary>
    public bool IsFinite => double.IsFinite(J1) && double.IsFinite(J2) && double.IsFinite(J3) && double.IsFinite(J4) && double.IsFinite(J5) && double.IsFinite(J6);

    /// <summary>Component-wise sum.</summary>
    public static Joints operator +(Joints a, Joints b) => new(a.J1 + b.J1, a.J2 + b.J2, a.J3 + b.J3, a.J4 + b.J4, a.J5 + b.J5, a.J6 + b.J6);

    /// <summary>Component-wise difference.</summary>
    public static Joints operator -(Joints a, Joints b) => new(a.J1 - b.J1, a.J2 - b.J2, a.J3 - b.J3, a.J4 - b.J4, a.J5 - b.J5, a.J6 - b.J6);

    /// <summary>Square root of the sum of the squared joint values, as in the original.</summary>
    public double Norm() => Math.Sqrt(NormSq());

    /// <summary>Sum of the squared joint values, as in the original.</summary>
    public double NormSq() => J1 * J1 + J2 * J2 + J3 * J3 + J4 * J4 + J5 * J5 + J6 * J6;

    /// <summary>True when every joint differs by less than <paramref name="tolerance"/> degrees.</summary>
    public bool IsSimilar(Joints other, double tolerance = 1e-6)
    {
        for (int i = 0; i < Count; i++)
        {
            if (Math.Abs(this[i] - other[i]) >= tolerance)
            {
                return false;
            }
        }
        return true;
    }

    /// <summary>Text such as <c>[0, 0, 0, 0, 90, 0]</c> (3 decimals).</summary>
    public override string ToString() =>
        $"[{Num.F(J1, 3)}, {Num.F(J2, 3)}, {Num.F(J3, 3)}, {Num.F(J4, 3)}, {Num.F(J5, 3)}, {Num.F(J6, 3)}]";

    internal Joints RequireFinite(string name)
    {
        if (!IsFinite)
        {
            throw new ArgumentException($"{name} must contain six finite numbers.", name);
        }
        return this;
    }
}

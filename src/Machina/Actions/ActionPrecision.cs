namespace Machina;

/// <summary>Sets (<c>PrecisionTo</c>) or changes (<c>Precision</c>) the blend radius of the following motions, in mm: how close the robot must pass to each target (0 = stop exactly on it).</summary>
public sealed record ActionPrecision : RobotAction
{
    /// <summary>Creates a precision action; <paramref name="precision"/> in mm.</summary>
    public ActionPrecision(double precision, bool relative)
    {
        Precision = Num.Finite(precision, nameof(precision));
        if (!relative && precision < 0)
        {
            throw new ArgumentException($"Precision (blend radius) cannot be negative, but it was {Num.G(precision)} mm.", nameof(precision));
        }
        Relative = relative;
    }

    /// <summary>The blend radius (absolute) or its change (relative), mm.</summary>
    public double Precision { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Precision;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "Precision" : "PrecisionTo", Precision);

    /// <inheritdoc/>
    public override string Describe() => Relative
        ? $"{InstructionText.Change(Precision)} precision radius by {Num.G(Precision)} mm"
        : $"Set precision radius to {Num.G(Precision)} mm";
}

namespace Machina;

/// <summary>Sets (<c>AccelerationTo</c>) or changes (<c>Acceleration</c>) the acceleration of the following motions, in mm/s² (and deg/s²). 0 means the controller's default.</summary>
public sealed record ActionAcceleration : RobotAction
{
    /// <summary>Creates an acceleration action; <paramref name="acceleration"/> in mm/s².</summary>
    public ActionAcceleration(double acceleration, bool relative)
    {
        Acceleration = Num.Finite(acceleration, nameof(acceleration));
        if (!relative && acceleration < 0)
        {
            throw new ArgumentException($"Acceleration cannot be negative, but it was {Num.G(acceleration)} mm/s^2.", nameof(acceleration));
        }
        Relative = relative;
    }

    /// <summary>The acceleration (absolute) or its change (relative), mm/s².</summary>
    public double Acceleration { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Acceleration;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "Acceleration" : "AccelerationTo", Acceleration);

    /// <inheritdoc/>
    public override string Describe() => Relative
        ? $"{InstructionText.Change(Acceleration)} motion acceleration by {Num.G(Acceleration)} mm/s^2 or deg/s^2"
        : $"Set motion acceleration to {Num.G(Acceleration)} mm/s^2 or deg/s^2";
}

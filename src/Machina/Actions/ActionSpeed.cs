namespace Machina;

/// <summary>Sets (<c>SpeedTo</c>) or changes (<c>Speed</c>) the speed of the following motions, in mm/s (and deg/s for rotations).</summary>
public sealed record ActionSpeed : RobotAction
{
    /// <summary>Creates a speed action; <paramref name="speed"/> in mm/s.</summary>
    public ActionSpeed(double speed, bool relative)
    {
        Speed = Num.Finite(speed, nameof(speed));
        if (!relative && speed <= 0)
        {
            throw new ArgumentException($"Speed must be greater than 0 mm/s, but it was {Num.G(speed)}.", nameof(speed));
        }
        Relative = relative;
    }

    /// <summary>The speed (absolute) or the change of speed (relative), mm/s.</summary>
    public double Speed { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Speed;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "Speed" : "SpeedTo", Speed);

    /// <inheritdoc/>
    public override string Describe() => Relative
        ? $"{InstructionText.Change(Speed)} motion speed by {Num.G(Speed)} mm/s or deg/s"
        : $"Set motion speed to {Num.G(Speed)} mm/s or deg/s";
}

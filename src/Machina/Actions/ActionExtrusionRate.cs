namespace Machina;

/// <summary>Sets (<c>ExtrusionRateTo</c>) or changes (<c>ExtrusionRate</c>) how much filament is pushed per mm of travel (mm/mm).</summary>
public sealed record ActionExtrusionRate : RobotAction
{
    /// <summary>Creates an extrusion-rate action, mm of filament per mm of travel.</summary>
    public ActionExtrusionRate(double rate, bool relative)
    {
        Rate = Num.Finite(rate, nameof(rate));
        if (!relative && rate < 0)
        {
            throw new ArgumentException($"Extrusion rate cannot be negative, but it was {Num.G(rate)}.", nameof(rate));
        }
        Relative = relative;
    }

    /// <summary>The rate (absolute) or its change (relative), mm of filament per mm of travel.</summary>
    public double Rate { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.ExtrusionRate;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "ExtrusionRate" : "ExtrusionRateTo", Rate);

    /// <inheritdoc/>
    public override string Describe() => Relative
        ? $"{InstructionText.Change(Rate)} extrusion rate by {Num.G(Rate)} mm/mm"
        : $"Set extrusion rate to {Num.G(Rate)} mm/mm";
}

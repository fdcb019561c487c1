namespace Machina;

/// <summary>Pauses the robot for a time, in milliseconds.</summary>
public sealed record ActionWait : RobotAction
{
    /// <summary>Creates a pause of <paramref name="millis"/> milliseconds (0 or more).</summary>
    public ActionWait(long millis)
    {
        if (millis < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(millis), millis, "A wait cannot be negative; give milliseconds, 0 or more.");
        }
        Millis = millis;
    }

    /// <summary>Duration of the pause, ms.</summary>
    public long Millis { get; }

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Wait;

    /// <inheritdoc/>
    public override string ToInstruction() => $"Wait({Num.I(Millis)});";

    /// <inheritdoc/>
    public override string Describe() => $"Wait {Num.I(Millis)} ms";
}

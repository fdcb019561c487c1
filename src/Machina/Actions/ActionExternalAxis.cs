namespace Machina;

/// <summary>Sets (<c>ExternalAxisTo</c>) or changes (<c>ExternalAxis</c>) one external axis (track, positioner) used by the following targets: mm or degrees.</summary>
public sealed record ActionExternalAxis : RobotAction
{
    /// <summary>Creates an external-axis action for axis 1..6.</summary>
    public ActionExternalAxis(int axisNumber, double value, ExternalAxesTarget target, bool relative)
    {
        if (axisNumber < 1 || axisNumber > ExternalAxes.Count)
        {
            throw new ArgumentOutOfRangeException(nameof(axisNumber), axisNumber, "External axis numbers are 1 to 6.");
        }
        AxisNumber = axisNumber;
        Value = Num.Finite(value, nameof(value));
        Target = EnumText.RequireDefined(target, nameof(target));
        Relative = relative;
    }

    /// <summary>The axis number, 1 to 6.</summary>
    public int AxisNumber { get; }

    /// <summary>The new value (absolute) or the change (relative), mm or degrees.</summary>
    public double Value { get; }

    /// <summary>Which targets the value applies to.</summary>
    public ExternalAxesTarget Target { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.ExternalAxis;

    /// <inheritdoc/>
    public override string ToInstruction()
    {
        string name = Relative ? "ExternalAxis" : "ExternalAxisTo";
        string target = Target == ExternalAxesTarget.All ? "" : $",\"{Target}\"";
        return $"{name}({Num.I(AxisNumber)},{Num.R(Value)}{target});";
    }

    /// <inheritdoc/>
    public override string Describe()
    {
        string head = Relative ? $"Increase external axis #{AxisNumber} by {Num.G(Value)}" : $"Set external axis #{AxisNumber} to {Num.G(Value)}";
        return Target switch
        {
            ExternalAxesTarget.Cartesian => head + " for cartesian targets.",
            ExternalAxesTarget.Joint => head + " for joint targets.",
            _ => head,
        };
    }
}

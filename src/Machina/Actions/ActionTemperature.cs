namespace Machina;

/// <summary>Sets (<c>TemperatureTo</c>) or changes (<c>Temperature</c>) the temperature of a 3D printer part, in °C, optionally waiting until it is reached.</summary>
public sealed record ActionTemperature : RobotAction
{
    /// <summary>Creates a temperature action; <paramref name="temperature"/> in °C.</summary>
    public ActionTemperature(double temperature, RobotPartType part, bool wait, bool relative)
    {
        Temperature = Num.Finite(temperature, nameof(temperature));
        if (!relative && temperature < 0)
        {
            throw new ArgumentException($"Temperature cannot be below 0 °C, but it was {Num.G(temperature)}.", nameof(temperature));
        }
        Part = EnumText.RequireDefined(part, nameof(part));
        Wait = wait;
        Relative = relative;
    }

    /// <summary>The temperature (absolute) or its change (relative), °C.</summary>
    public double Temperature { get; }

    /// <summary>The heated part.</summary>
    public RobotPartType Part { get; }

    /// <summary>True to wait until the temperature is reached.</summary>
    public bool Wait { get; }

    /// <summary>True for a change, false for a new value.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Temperature;

    /// <inheritdoc/>
    public override string ToInstruction() =>
        $"{(Relative ? "Temperature" : "TemperatureTo")}({Num.R(Temperature)},\"{Part}\",{InstructionText.Bool(Wait)});";

    /// <inheritdoc/>
    public override string Describe()
    {
        string wait = Wait ? " and wait" : "";
        return Relative
            ? $"{InstructionText.Change(Temperature)} {Part} temperature by {Num.F(Temperature, 0)} C{wait}"
            : $"Set {Part} temperature to {Num.F(Temperature, 0)} C{wait}";
    }
}

namespace Machina;

/// <summary>Turns a digital output of the controller (or of the tool) on or off.</summary>
public sealed record ActionIODigital : RobotAction
{
    /// <summary>Creates a digital write; <paramref name="pinName"/> is a number such as "2" or a named signal such as "DO_15".</summary>
    public ActionIODigital(string pinName, bool on, bool isToolPin)
    {
        PinName = IOPin.Validate(pinName);
        On = on;
        IsToolPin = isToolPin;
    }

    /// <summary>The output's number or name.</summary>
    public string PinName { get; }

    /// <summary>True to turn the output on.</summary>
    public bool On { get; }

    /// <summary>True for an output on the tool flange rather than the controller.</summary>
    public bool IsToolPin { get; }

    /// <summary>True when the pin is given as a whole number.</summary>
    public bool IsDigit => IOPin.TryNumber(PinName, out _);

    /// <summary>The pin number when <see cref="IsDigit"/>, else −1.</summary>
    public int PinNumber => IOPin.TryNumber(PinName, out int n) ? n : -1;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.IODigital;

    /// <inheritdoc/>
    public override string ToInstruction() =>
        $"WriteDigital({IOPin.Text(PinName)},{InstructionText.Bool(On)}{(IsToolPin ? ",True" : "")});";

    /// <inheritdoc/>
    public override string Describe() => $"Turn {(IsToolPin ? "tool " : "")}digital IO {IOPin.Text(PinName)} {(On ? "ON" : "OFF")}";
}

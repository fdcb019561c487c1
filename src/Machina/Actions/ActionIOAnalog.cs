namespace Machina;

/// <summary>Sets an analog output of the controller (or of the tool) to a value.</summary>
public sealed record ActionIOAnalog : RobotAction
{
    /// <summary>Creates an analog write; <paramref name="pinName"/> is a number such as "0" or a named signal such as "AO_1".</summary>
    public ActionIOAnalog(string pinName, double value, bool isToolPin)
    {
        PinName = IOPin.Validate(pinName);
        Value = Num.Finite(value, nameof(value));
        IsToolPin = isToolPin;
    }

    /// <summary>The output's number or name.</summary>
    public string PinName { get; }

    /// <summary>The value to write (its unit depends on the signal's configuration).</summary>
    public double Value { get; }

    /// <summary>True for an output on the tool flange rather than the controller.</summary>
    public bool IsToolPin { get; }

    /// <summary>True when the pin is given as a whole number.</summary>
    public bool IsDigit => IOPin.TryNumber(PinName, out _);

    /// <summary>The pin number when <see cref="IsDigit"/>, else −1.</summary>
    public int PinNumber => IOPin.TryNumber(PinName, out int n) ? n : -1;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.IOAnalog;

    /// <inheritdoc/>
    public override string ToInstruction() =>
        $"WriteAnalog({IOPin.Text(PinName)},{Num.R(Value)}{(IsToolPin ? ",True" : "")});";

    /// <inheritdoc/>
    public override string Describe() => $"Set {(IsToolPin ? "tool " : "")}analog IO {IOPin.Text(PinName)} to {Num.G(Value)}";
}

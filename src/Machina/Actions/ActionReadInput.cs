namespace Machina;

/// <summary>
/// Reads a digital or analog input of the controller (or of the tool). Online the value comes back with the controller's
/// acknowledgement (see <see cref="Robot.ReadDigitalAsync(string, bool, CancellationToken)"/> and
/// <see cref="ActionExecutedArgs.ReadValue"/>); offline the program stores it in a variable (machina_di or machina_ai).
/// </summary>
public sealed record ActionReadInput : RobotAction
{
    /// <summary>Creates a read; <paramref name="pinName"/> is a number such as "2" or a named signal such as "DI_Part".</summary>
    public ActionReadInput(string pinName, bool isAnalog, bool isToolPin)
    {
        PinName = IOPin.Validate(pinName);
        IsAnalog = isAnalog;
        IsToolPin = isToolPin;
    }

    /// <summary>The input's number or name.</summary>
    public string PinName { get; }

    /// <summary>True for an analog input (a number), false for a digital one (on or off).</summary>
    public bool IsAnalog { get; }

    /// <summary>True for an input on the tool flange rather than the controller.</summary>
    public bool IsToolPin { get; }

    /// <summary>True when the pin is given as a whole number.</summary>
    public bool IsDigit => IOPin.TryNumber(PinName, out _);

    /// <summary>The pin number when <see cref="IsDigit"/>, else −1.</summary>
    public int PinNumber => IOPin.TryNumber(PinName, out int n) ? n : -1;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.ReadInput;

    /// <inheritdoc/>
    public override string ToInstruction() =>
        $"{(IsAnalog ? "ReadAnalog" : "ReadDigital")}({IOPin.Text(PinName)}{(IsToolPin ? ",True" : "")});";

    /// <inheritdoc/>
    public override string Describe() =>
        $"Read {(IsToolPin ? "tool " : "")}{(IsAnalog ? "analog" : "digital")} input {IOPin.Text(PinName)}";
}

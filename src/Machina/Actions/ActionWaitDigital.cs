namespace Machina;

/// <summary>
/// Waits until a digital input of the controller (or of the tool) is on or off, at most a time when a limit is given.
/// A wait that times out stops the program with an error, as the controller's own wait does.
/// </summary>
public sealed record ActionWaitDigital : RobotAction
{
    /// <summary>
    /// Creates a wait for an input; <paramref name="pinName"/> is a number such as "2" or a named signal such as "DI_Part".
    /// <paramref name="timeoutMillis"/> is the longest wait in milliseconds; 0 waits as long as it takes.
    /// </summary>
    public ActionWaitDigital(string pinName, bool on, long timeoutMillis, bool isToolPin)
    {
        PinName = IOPin.Validate(pinName);
        if (timeoutMillis < 0)
        {
            throw new ArgumentOutOfRangeException(nameof(timeoutMillis), timeoutMillis, "A wait's time limit cannot be negative; give milliseconds, or 0 to wait as long as it takes.");
        }
        On = on;
        TimeoutMillis = timeoutMillis;
        IsToolPin = isToolPin;
    }

    /// <summary>The input's number or name.</summary>
    public string PinName { get; }

    /// <summary>True to wait until the input is on, false until it is off.</summary>
    public bool On { get; }

    /// <summary>The longest wait, ms; 0 = no limit.</summary>
    public long TimeoutMillis { get; }

    /// <summary>True for an input on the tool flange rather than the controller.</summary>
    public bool IsToolPin { get; }

    /// <summary>True when the pin is given as a whole number.</summary>
    public bool IsDigit => IOPin.TryNumber(PinName, out _);

    /// <summary>The pin number when <see cref="IsDigit"/>, else −1.</summary>
    public int PinNumber => IOPin.TryNumber(PinName, out int n) ? n : -1;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.WaitDigital;

    /// <inheritdoc/>
    public override string ToInstruction() =>
        $"WaitForDigital({IOPin.Text(PinName)},{InstructionText.Bool(On)}" +
        (IsToolPin ? $",{Num.I(TimeoutMillis)},True" : TimeoutMillis > 0 ? $",{Num.I(TimeoutMillis)}" : "") + ");";

    /// <inheritdoc/>
    public override string Describe() =>
        $"Wait for {(IsToolPin ? "tool " : "")}digital input {IOPin.Text(PinName)} {(On ? "ON" : "OFF")}" +
        (TimeoutMillis > 0 ? $" (at most {Num.I(TimeoutMillis)} ms)" : "");
}

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>
    /// Sets a digital input of the twin's IO configuration (DI_1 … DI_16), as a sensor wired to it would; the RAPID driver's
    /// WaitDI sees it. Only a started controller has inputs.
    /// </summary>
    /// <exception cref="InvalidOperationException">The controller does not run RAPID, is not started, or has no such input.</exception>
    public void SetDigitalInput(string signal, bool on)
    {
        ArgumentNullException.ThrowIfNull(signal);
        var twin = Twin ?? throw new InvalidOperationException("Only a started virtual ABB controller has inputs to set.");
        if (twin.Signal(signal) is not { Bank: "di" } input)
        {
            throw new InvalidOperationException($"The virtual ABB controller has no digital input \"{signal}\"; its inputs are DI_1 to DI_16.");
        }
        twin.SetBit(input.Bank, input.Index, on);
    }

    /// <summary>
    /// Sets an analog input of the twin's IO configuration (AI_1 … AI_4) to a value, as a sensor wired to it would; the RAPID
    /// driver's AInput sees it. Only a started controller has inputs.
    /// </summary>
    /// <exception cref="InvalidOperationException">The controller does not run RAPID, is not started, or has no such input.</exception>
    /// <exception cref="ArgumentOutOfRangeException">The value is not a finite number.</exception>
    public void SetAnalogInput(string signal, double value)
    {
        ArgumentNullException.ThrowIfNull(signal);
        if (!double.IsFinite(value))
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, "An analog input holds a finite number.");
        }
        var twin = Twin ?? throw new InvalidOperationException("Only a started virtual ABB controller has inputs to set.");
        if (twin.Signal(signal) is not { Bank: "ai" } input)
        {
            throw new InvalidOperationException($"The virtual ABB controller has no analog input \"{signal}\"; its analog inputs are AI_1 to AI_4.");
        }
        twin.SetNumber(input.Bank, input.Index, value);
    }
}

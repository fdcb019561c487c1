namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>
    /// Sets a digital input of the twin's IO configuration (DI_1 … DI_16), as a sensor wired to it would; the RAPID driver's
    /// WaitDI sees it. Only a controller that runs RAPID (<see cref="VirtualAbbControllerOptions.RunsRapid"/>) has inputs.
    /// </summary>
    /// <exception cref="InvalidOperationException">The controller does not run RAPID, is not started, or has no such input.</exception>
    public void SetDigitalInput(string signal, bool on)
    {
        ArgumentNullException.ThrowIfNull(signal);
        var twin = Twin ?? throw new InvalidOperationException("Only a started virtual ABB controller that runs RAPID (RunsRapid) has inputs to set.");
        if (twin.Signal(signal) is not { Bank: "di" } input)
        {
            throw new InvalidOperationException($"The virtual ABB controller has no digital input \"{signal}\"; its inputs are DI_1 to DI_16.");
        }
        twin.Io.SetBit(input.Bank, input.Index, on);
    }
}

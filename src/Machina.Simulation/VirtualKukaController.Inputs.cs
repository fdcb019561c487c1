namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// Sets digital input <c>$IN[number]</c> (1 to 4096), as a sensor wired to it would; the KRL driver's WAIT FOR sees it.
    /// Only a started controller has inputs.
    /// </summary>
    /// <exception cref="InvalidOperationException">The controller is not started.</exception>
    /// <exception cref="ArgumentOutOfRangeException">There is no such input.</exception>
    public void SetDigitalInput(int number, bool on)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(number, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(number, 4096);
        var twin = Twin ?? throw new InvalidOperationException("Only a started virtual KUKA controller has inputs to set.");
        twin.SetInput(number, on);
    }
}

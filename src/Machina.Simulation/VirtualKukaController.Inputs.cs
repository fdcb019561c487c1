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

    /// <summary>
    /// Sets analog input <c>$ANIN[number]</c> (1 to 32) to a value from −1 to 1 (a fraction of the input's range), as a sensor
    /// wired to it would. Only a started controller that runs KRL (<see cref="VirtualKukaControllerOptions.RunsKrl"/>) has inputs.
    /// </summary>
    /// <exception cref="InvalidOperationException">The controller does not run KRL or is not started.</exception>
    /// <exception cref="ArgumentOutOfRangeException">There is no such input, or the value is outside −1 to 1.</exception>
    public void SetAnalogInput(int number, double value)
    {
        ArgumentOutOfRangeException.ThrowIfLessThan(number, 1);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(number, 32);
        if (!(value >= -1 && value <= 1))
        {
            throw new ArgumentOutOfRangeException(nameof(value), value, "$ANIN holds values from -1 to 1.");
        }
        var twin = Twin ?? throw new InvalidOperationException("Only a started virtual KUKA controller that runs KRL (RunsKrl) has inputs to set.");
        twin.SetAnalogInput(number, value);
    }
}

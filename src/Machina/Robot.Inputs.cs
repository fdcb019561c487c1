namespace Machina;

public sealed partial class Robot
{
    /// <summary>
    /// Waits until digital input number <paramref name="pinNumber"/> is on (or off), at most <paramref name="timeoutMillis"/>
    /// ms (0 = as long as it takes); a wait that times out stops the program (online: the action fails).
    /// </summary>
    public bool WaitForDigital(int pinNumber, bool isOn, long timeoutMillis = 0, bool toolPin = false) =>
        WaitForDigital(PinText(pinNumber), isOn, timeoutMillis, toolPin);

    /// <summary>Waits until a digital input, given by number or signal name, is on (or off), at most a time in ms (0 = no limit).</summary>
    public bool WaitForDigital(string pinId, bool isOn, long timeoutMillis = 0, bool toolPin = false) =>
        Issue(Arg.Renamed("pin", nameof(pinId), (pinId, isOn, timeoutMillis, toolPin),
            static a => new ActionWaitDigital(a.pinId, a.isOn, a.timeoutMillis, a.toolPin)));

    /// <summary>
    /// Reads digital input number <paramref name="pinNumber"/> when the program gets there: offline into the program variable
    /// machina_di, online its value arrives with the action's <see cref="ActionExecuted"/> (<see cref="ActionExecutedArgs.ReadValue"/>).
    /// </summary>
    public bool ReadDigital(int pinNumber, bool toolPin = false) => ReadDigital(PinText(pinNumber), toolPin);

    /// <summary>Reads a digital input, given by number or signal name, when the program gets there (see <see cref="ReadDigital(int, bool)"/>).</summary>
    public bool ReadDigital(string pinId, bool toolPin = false) => Issue(NewRead(pinId, false, toolPin));

    /// <summary>
    /// Reads analog input number <paramref name="pinNumber"/> when the program gets there: offline into the program variable
    /// machina_ai, online its value arrives with the action's <see cref="ActionExecuted"/> (<see cref="ActionExecutedArgs.ReadValue"/>).
    /// </summary>
    public bool ReadAnalog(int pinNumber, bool toolPin = false) => ReadAnalog(PinText(pinNumber), toolPin);

    /// <summary>Reads an analog input, given by number or signal name, when the program gets there (see <see cref="ReadAnalog(int, bool)"/>).</summary>
    public bool ReadAnalog(string pinId, bool toolPin = false) => Issue(NewRead(pinId, true, toolPin));

    /// <summary>
    /// Online: issues a read of a digital input and returns its value once the controller ran it (after every action issued
    /// before it). Offline there is no controller to answer, so it throws.
    /// </summary>
    /// <exception cref="InvalidOperationException">The robot is offline.</exception>
    /// <exception cref="MachinaException">The read failed, was cancelled by an earlier failure or a stop, or the link was lost first.</exception>
    public Task<bool> ReadDigitalAsync(int pinNumber, bool toolPin = false, CancellationToken cancellationToken = default) =>
        ReadDigitalAsync(PinText(pinNumber), toolPin, cancellationToken);

    /// <summary>Online: reads a digital input, given by number or signal name, and returns its value once the controller ran the read.</summary>
    public Task<bool> ReadDigitalAsync(string pinId, bool toolPin = false, CancellationToken cancellationToken = default) =>
        IsOn(ReadValueAsync(NewRead(pinId, false, toolPin), cancellationToken));

    private static async Task<bool> IsOn(Task<double> value) => await value.ConfigureAwait(false) != 0;

    /// <summary>
    /// Online: issues a read of an analog input and returns its value once the controller ran it (after every action issued
    /// before it). Offline there is no controller to answer, so it throws.
    /// </summary>
    /// <exception cref="InvalidOperationException">The robot is offline.</exception>
    /// <exception cref="MachinaException">The read failed, was cancelled by an earlier failure or a stop, or the link was lost first.</exception>
    public Task<double> ReadAnalogAsync(int pinNumber, bool toolPin = false, CancellationToken cancellationToken = default) =>
        ReadAnalogAsync(PinText(pinNumber), toolPin, cancellationToken);

    /// <summary>Online: reads an analog input, given by number or signal name, and returns its value once the controller ran the read.</summary>
    public Task<double> ReadAnalogAsync(string pinId, bool toolPin = false, CancellationToken cancellationToken = default) =>
        ReadValueAsync(NewRead(pinId, true, toolPin), cancellationToken);

    private static ActionReadInput NewRead(string pinId, bool analog, bool toolPin) =>
        Arg.Renamed("pin", nameof(pinId), (pinId, analog, toolPin), static a => new ActionReadInput(a.pinId, a.analog, a.toolPin));

    private Task<double> ReadValueAsync(ActionReadInput read, CancellationToken cancellationToken)
    {
        ThrowIfDisposed("read an input");
        OnlineSession session = RequireSession("wait for an input's value (offline, ReadDigital and ReadAnalog store it in the program)");
        Issue(read);
        return session.ReadValueAsync(read.Id, cancellationToken);
    }
}

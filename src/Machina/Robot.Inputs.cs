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
}

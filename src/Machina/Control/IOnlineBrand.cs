namespace Machina;

/// <summary>
/// One brand's online support, everything <see cref="OnlineSession"/> needs to know about it: how to make a link to its
/// controller, which actions its driver can run, and its controller-side driver files. A brand implements this once, in
/// its own folder (<c>Brands/&lt;Brand&gt;/Online/</c>), and registers it in <see cref="OnlineBrands"/>.
/// </summary>
internal interface IOnlineBrand
{
    /// <summary>The brand this support is for.</summary>
    RobotType Brand { get; }

    /// <summary>A new, unconnected link to a controller of this brand (one per connection).</summary>
    IDeviceDriver CreateDriver(DeviceContext context);

    /// <summary>
    /// Why this brand's driver cannot run <paramref name="action"/> (a sentence naming the action), or null when it can.
    /// Called when the action is issued online, before it changes anything, so that nothing unsendable is ever accepted.
    /// </summary>
    string? WhyCannotStream(RobotAction action);

    /// <summary>
    /// Encodes <paramref name="action"/> for the wire from <paramref name="after"/>, the state it leads to: the frame the driver
    /// sends. <paramref name="refusal"/> says why the wire cannot carry it (a relative move or speed beyond the wire's numbers),
    /// or is null. Called once the action is applied to the issue cursor (a refusal undoes it, so nothing is accepted that would
    /// fail when it is sent; the frame travels with the action) and again only when a reconnect re-targets the action.
    /// </summary>
    /// <exception cref="NotSupportedException">The driver has no instruction for the action (issuing refuses those first).</exception>
    ActionFrame Encode(RobotAction action, RobotCursor after, out string? refusal);

    /// <summary>The controller-side driver files by file name, with the connection parameters (HOSTNAME, PORT…) filled in.</summary>
    IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters);
}

/// <summary>Questions asked of a brand's codec.</summary>
internal static class OnlineBrandExtensions
{
    /// <summary>Why the wire cannot carry <paramref name="action"/> from <paramref name="after"/>, the state it leads to, or null (the frame is dropped).</summary>
    internal static string? WhyCannotSend(this IOnlineBrand brand, RobotAction action, RobotCursor after)
    {
        brand.Encode(action, after, out string? refusal);
        return refusal;
    }
}

/// <summary>What a device driver gets from its robot: where to log, which clock to use, and the robot's settings.</summary>
/// <param name="Logger">The robot's log.</param>
/// <param name="Time">The robot's clock (tests drive it by hand).</param>
/// <param name="RobotName">The robot's name, for messages.</param>
/// <param name="Model">The robot's arm model, or null when it has none.</param>
/// <param name="MotionUpdateRate">How many live pose reports per second to ask the controller for (Hz).</param>
internal sealed record DeviceContext(RobotLogger Logger, TimeProvider Time, string RobotName, RobotModel? Model, double MotionUpdateRate);

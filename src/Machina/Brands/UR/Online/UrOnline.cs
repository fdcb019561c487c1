namespace Machina;

/// <summary>
/// UR online: Machina's URScript driver (drivers/ur) sent once over a script port, which connects back to a server the
/// host opens; live state over RTDE; the dashboard server to resume after a stop (docs/protocol-ur.md).
/// </summary>
internal sealed class UrOnline : IOnlineBrand
{
    /// <inheritdoc/>
    public RobotType Brand => RobotType.UR;

    /// <inheritdoc/>
    public IDeviceDriver CreateDriver(DeviceContext context) => new UrDriver(context);

    /// <inheritdoc/>
    /// <remarks>The encoder's own rule (<see cref="UrActionEncoder.WhyNot(RobotAction)"/>): verbs and outputs the driver has none for.</remarks>
    public string? WhyCannotStream(RobotAction action) => UrActionEncoder.WhyNot(action);

    /// <inheritdoc/>
    /// <remarks>The encoder itself: what it cannot scale into its integers, or a speed that rounds to 0, is refused with the reason.</remarks>
    public string? WhyCannotSend(RobotAction action, RobotCursor after)
    {
        Span<int> values = stackalloc int[UrActionEncoder.MaxValues];
        return UrActionEncoder.TryEncode(action, after, values, out _);
    }

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        new Dictionary<string, string>
        {
            [UrDriverScript.FileName] = UrDriverScript.For(DriverParameters.Require(parameters, "HOSTNAME"), DriverParameters.Port(parameters)),
        };
}

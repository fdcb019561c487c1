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
    public ActionFrame Encode(RobotAction action, RobotCursor after, out string? refusal)
    {
        Span<int> values = stackalloc int[UrActionEncoder.MaxValues];
        refusal = UrActionEncoder.TryEncode(action, after, values, out int count);
        if (refusal is not null || count == 0)
        {
            return ActionFrame.Nothing;
        }
        Span<byte> encoded = stackalloc byte[UrActionEncoder.MaxValues * 4];
        int length = UrWire.Write(values[..count], encoded);
        return new ActionFrame(encoded[..length].ToArray(), true);
    }

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        new Dictionary<string, string>
        {
            [UrDriverScript.FileName] = UrDriverScript.For(DriverParameters.Require(parameters, "HOSTNAME"), DriverParameters.Port(parameters)),
        };
}

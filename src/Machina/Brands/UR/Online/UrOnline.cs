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
    public string? WhyCannotStream(RobotAction action) => action switch
    {
        ActionArcMotion or ActionExternalAxis or ActionArmAngle or ActionCustomCode or ActionCoordinates
            or ActionTemperature or ActionExtrusion or ActionExtrusionRate =>
            $"\"{action}\" cannot be streamed to a UR robot: Machina's UR driver has no instruction for it.",
        ActionIODigital { PinNumber: < 0 } d => $"\"{action}\": a UR digital output is a number, not \"{d.PinName}\".",
        ActionIOAnalog { PinNumber: < 0 } a => $"\"{action}\": a UR analog output is a number, not \"{a.PinName}\".",
        ActionIOAnalog { IsToolPin: true } => $"\"{action}\": UR tools have no analog outputs.",
        _ => null,
    };

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        new Dictionary<string, string>
        {
            [UrDriverScript.FileName] = UrDriverScript.For(DriverParameters.Require(parameters, "HOSTNAME"), DriverParameters.Port(parameters)),
        };
}

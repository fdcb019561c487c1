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
        _ => WhyBeyondTheWire(action),
    };

    /// <summary>
    /// Why a value of the action cannot travel in the driver's 32-bit integers (0.1 mm, 1e-4 rad, 1 ms, 1 g, 1e-6 of an analog
    /// unit), or null. Absolute values only: where a relative action leads is known when it is applied.
    /// </summary>
    private static string? WhyBeyondTheWire(RobotAction action)
    {
        bool fits = action switch
        {
            ActionTranslation { Relative: false } t => Fits(t.Translation),
            ActionTransformation { Relative: false } t => Fits(t.Translation),
            ActionAxes { Relative: false } a => Enumerable.Range(0, Joints.Count).All(i => Fits(a.Joints[i] * UrScriptText.Rad * UrWire.FactorRadian)),
            ActionWait w => w.Millis < int.MaxValue,
            ActionSpeed { Relative: false } v => FitsMm(v.Speed),
            ActionAcceleration { Relative: false } v => FitsMm(v.Acceleration),
            ActionPrecision { Relative: false } v => FitsMm(v.Precision),
            ActionIOAnalog a => Fits(a.Value * UrWire.FactorAnalog),
            ActionDefineTool d => Fits(d.Tool.TcpPosition) && Fits(d.Tool.Weight * UrWire.FactorKilogram),
            _ => true,
        };
        return fits ? null : TooLarge(action);
    }

    /// <inheritdoc/>
    /// <remarks>The encoder's own rule: what it cannot scale into 32-bit integers (a relative move or speed gone too far) is refused.</remarks>
    public string? WhyCannotSend(RobotAction action, RobotCursor after)
    {
        Span<int> values = stackalloc int[UrActionEncoder.MaxValues];
        try
        {
            UrActionEncoder.Encode(action, after, values);
            return null;
        }
        catch (ArgumentOutOfRangeException)
        {
            return TooLarge(action);
        }
    }

    private static string TooLarge(RobotAction action) =>
        $"\"{Abbreviate(action.ToInstruction())}\" cannot be streamed to a UR robot: a value is too large for its driver's 32-bit numbers.";

    private static bool Fits(Vector mm) => FitsMm(mm.X) && FitsMm(mm.Y) && FitsMm(mm.Z);

    private static bool FitsMm(double mm) => Fits(mm * UrScriptText.Mm * UrWire.FactorMetre);

    private static bool Fits(double scaled) => Math.Abs(scaled) < int.MaxValue;

    private static string Abbreviate(string text) => text.Length <= 60 ? text : text[..57] + "...";

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        new Dictionary<string, string>
        {
            [UrDriverScript.FileName] = UrDriverScript.For(DriverParameters.Require(parameters, "HOSTNAME"), DriverParameters.Port(parameters)),
        };
}

namespace Machina;

/// <summary>ABB online: Machina's RAPID driver and monitor (drivers/abb), reached over TCP (spec online §6).</summary>
internal sealed class AbbOnline : IOnlineBrand
{
    /// <inheritdoc/>
    public RobotType Brand => RobotType.ABB;

    /// <inheritdoc/>
    public IDeviceDriver CreateDriver(DeviceContext context) => new AbbDriver(context.Logger, context.Time);

    /// <inheritdoc/>
    /// <remarks>
    /// Refuses the texts the encoder cannot put on the wire (signal names and custom statements that are not plain ASCII, hold
    /// '"' or ';', or do not fit a RAPID string), with the encoder's own rules; messages are made safe instead (TPWrite).
    /// </remarks>
    public string? WhyCannotStream(RobotAction action) => action switch
    {
        ActionIODigital digital => Refuse(action, AbbRequest.WhyTextCannotBeSent(digital.PinName)),
        ActionIOAnalog analog => Refuse(action, AbbRequest.WhyTextCannotBeSent(analog.PinName)),
        ActionCustomCode { IsDeclaration: false } custom => Refuse(action, AbbRequest.WhyStatementCannotBeSent(custom.Statement)),
        _ => null,
    };

    private static string? Refuse(RobotAction action, string? why) =>
        why is null ? null : $"{action.Type} ({Abbreviate(action.ToInstruction())}) cannot be streamed to an ABB robot: {why}";

    private static string Abbreviate(string text) => text.Length <= 60 ? text : text[..57] + "...";

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        AbbDriverModules.Create(
            DriverParameters.Require(parameters, "HOSTNAME"),
            DriverParameters.Port(parameters),
            DriverParameters.Number(parameters, "MONITOR_RATE", AbbDriverModules.DefaultMonitorRate, "a number of reports per second"));
}

namespace Machina;

/// <summary>ABB online: Machina's RAPID driver and monitor (drivers/abb), reached over TCP (spec online §6).</summary>
internal sealed class AbbOnline : IOnlineBrand
{
    /// <inheritdoc/>
    public RobotType Brand => RobotType.ABB;

    /// <inheritdoc/>
    public IDeviceDriver CreateDriver(DeviceContext context) => new AbbDriver(context.Logger, context.Time);

    /// <inheritdoc/>
    public string? WhyCannotStream(RobotAction action) => null;

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        AbbDriverModules.Create(
            DriverParameters.Require(parameters, "HOSTNAME"),
            DriverParameters.Port(parameters),
            DriverParameters.Number(parameters, "MONITOR_RATE", AbbDriverModules.DefaultMonitorRate, "a number of reports per second"));
}

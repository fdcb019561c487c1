namespace Machina;

/// <summary>KUKA online: Machina's KRL driver and monitor (drivers/kuka) on EthernetKRL, reached over TCP (docs/protocol-kuka.md).</summary>
internal sealed class KukaOnline : IOnlineBrand
{
    /// <inheritdoc/>
    public RobotType Brand => RobotType.KUKA;

    /// <inheritdoc/>
    public IDeviceDriver CreateDriver(DeviceContext context) => throw new NotImplementedException();

    /// <inheritdoc/>
    public string? WhyCannotStream(RobotAction action) => KukaActionEncoder.WhyCannotStream(action);

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) => throw new NotImplementedException();
}

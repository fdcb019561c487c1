namespace Machina;

/// <summary>KUKA online: Machina's KRL driver and monitor (drivers/kuka) on EthernetKRL, reached over TCP (docs/protocol-kuka.md).</summary>
internal sealed class KukaOnline : IOnlineBrand
{
    /// <inheritdoc/>
    public RobotType Brand => RobotType.KUKA;

    /// <inheritdoc/>
    public IDeviceDriver CreateDriver(DeviceContext context) => new KukaDriver(context);

    /// <inheritdoc/>
    public string? WhyCannotStream(RobotAction action) => KukaActionEncoder.WhyCannotStream(action);

    /// <inheritdoc/>
    /// <remarks>The driver reads every number into a KRL <c>REAL</c>, a 32-bit float: a value beyond ±3.4E+38 is refused.</remarks>
    public string? WhyCannotSend(RobotAction action, RobotCursor after)
    {
        if (KukaActionEncoder.Encode(action, action.Id, after) is not KukaInstruction instruction)
        {
            return null;
        }
        KukaValues values = instruction.Values;
        for (int i = 0; i < KukaProtocol.ValueCountOf(instruction.Code); i++)
        {
            if (Math.Abs(values[i]) > float.MaxValue)
            {
                return KukaActionEncoder.Refuse(action, $"{Num.G(values[i])} is beyond what a KRL REAL holds (±3.4E+38).");
            }
        }
        return null;
    }

    /// <inheritdoc/>
    public IReadOnlyDictionary<string, string> DriverModules(IReadOnlyDictionary<string, string> parameters) =>
        KukaDriverModules.Create(
            DriverParameters.Require(parameters, "HOSTNAME"),
            DriverParameters.Port(parameters),
            Advance(DriverParameters.Number(parameters, "ADVANCE", KukaDriverModules.DefaultAdvance, "a whole number from 0 to 5")));

    private static int Advance(double value) => value == Math.Floor(value) && value is >= 0 and <= 5
        ? (int)value
        : throw new ArgumentException($"ADVANCE must be a whole number from 0 to 5 (KRL's $ADVANCE), not {Num.G(value)}.", "parameters");
}

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
    /// Refuses IO pins that are not RAPID signal names (a number such as 1: the same rule as the RAPID compiler's), and the texts the
    /// encoder cannot put on the wire (custom statements that are not plain ASCII, hold '"' or ';', or do not fit a RAPID string),
    /// with the encoder's own rules; messages are made safe instead (TPWrite).
    /// </remarks>
    public string? WhyCannotStream(RobotAction action) => action switch
    {
        ActionIODigital digital => Refuse(action, AbbRequest.WhyTextCannotBeSent(digital.PinName) ?? RapidNames.WhyNotSignal(digital.PinName)),
        ActionReadInput read => Refuse(action, AbbRequest.WhyTextCannotBeSent(read.PinName) ?? RapidNames.WhyNotSignal(read.PinName)),
        ActionWaitDigital wait => Refuse(action, AbbRequest.WhyTextCannotBeSent(wait.PinName) ?? RapidNames.WhyNotSignal(wait.PinName)),
        ActionIOAnalog analog => Refuse(action, AbbRequest.WhyTextCannotBeSent(analog.PinName) ?? RapidNames.WhyNotSignal(analog.PinName)),
        ActionCustomCode { IsDeclaration: false } custom => Refuse(action, AbbRequest.WhyStatementCannotBeSent(custom.Statement)),
        _ => null,
    };

    /// <inheritdoc/>
    /// <remarks>
    /// The requests carry the wire id (RAPID reads ids as 32-bit floats, <see cref="AbbDriver.WireId(int)"/>). The driver reads
    /// every number into a RAPID <c>num</c>, a 32-bit float: a value beyond ±3.4E+38 is refused.
    /// </remarks>
    public ActionFrame Encode(RobotAction action, RobotCursor after, out string? refusal)
    {
        const int StackBytes = 512;
        refusal = null;
        var requests = new AbbRequestBlock();
        int wireId = action.Id < 0 ? 0 : AbbDriver.WireId(action.Id);
        if (AbbActionEncoder.Encode(action.Id is >= 0 and <= AbbRequest.MaxId ? action : WithWireId(action), after, ref requests) == 0)
        {
            return ActionFrame.Nothing;
        }
        int length = 0;
        bool acknowledged = false;
        for (int r = 0; r < requests.Count; r++)
        {
            AbbRequest request = requests[r];
            for (int i = 0; i < request.ParameterCount && refusal is null; i++)
            {
                if (Math.Abs(request[i]) > float.MaxValue)
                {
                    refusal = Refuse(action, $"{Num.G(request[i])} is beyond what a RAPID number holds (±3.4E+38).");
                }
            }
            length += request.MaxEncodedLength;
            acknowledged |= request.Id == wireId;
        }
        // Written at the upper bound on the stack, kept at the exact length: one array per frame.
        Span<byte> bytes = length <= StackBytes ? stackalloc byte[StackBytes] : new byte[length];
        length = 0;
        for (int r = 0; r < requests.Count; r++)
        {
            length += requests[r].EncodeTo(bytes[length..]);
        }
        return new ActionFrame(bytes[..length].ToArray(), acknowledged);
    }

    /// <summary>
    /// A copy with an id the encoder accepts: the wire id the driver will send, or 0 for an action not issued yet (a multi-statement
    /// <c>Do</c> checks its actions before they get ids). Only the numbers matter here.
    /// </summary>
    private static RobotAction WithWireId(RobotAction action)
    {
        RobotAction copy = action.CloneUnissued();
        copy.Id = action.Id < 0 ? 0 : AbbDriver.WireId(action.Id);
        return copy;
    }

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

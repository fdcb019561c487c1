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
    /// <remarks>
    /// One batch of one instruction. The driver reads every number into a KRL <c>REAL</c>, a 32-bit float: a value beyond
    /// ±3.4E+38 is refused. What the controller will not get (a message cut to its length, a tool's load) is the frame's note.
    /// </remarks>
    public ActionFrame Encode(RobotAction action, RobotCursor after, out string? refusal)
    {
        refusal = null;
        if (KukaActionEncoder.Encode(action, action.Id, after) is not KukaInstruction instruction)
        {
            return ActionFrame.Nothing;
        }
        KukaValues values = instruction.Values;
        for (int i = 0; i < KukaProtocol.ValueCountOf(instruction.Code) && refusal is null; i++)
        {
            if (Math.Abs(values[i]) > float.MaxValue)
            {
                refusal = KukaActionEncoder.Refuse(action, $"{Num.G(values[i])} is beyond what a KRL REAL holds (±3.4E+38).");
            }
        }
        string? note = null;
        if (action is ActionMessage message && KukaActionEncoder.IsTruncated(message.Message))
        {
            note = $"KUKA messages hold {KukaProtocol.MaxTextLength} characters: the message of action {action.Id} is shown cut to \"{instruction.Text}\".";
        }
        else if (action is ActionAttachTool && after.Tool is Tool tool)
        {
            note = $"The weight and centre of gravity of tool \"{tool.Name}\" are not sent to KUKA controllers; set its load data on the controller.";
        }
        KukaText batch = instruction.WriteBatch(stackalloc char[KukaInstruction.StackBatchChars]);
        // A move, a setting, a short message: the characters straight into the frame's bytes, no builder per action.
        return new ActionFrame(batch.Builder is { } built ? Ascii(built) : Ascii(batch.Written), true, note);
    }

    private static byte[] Ascii(ReadOnlySpan<char> text)
    {
        var bytes = new byte[text.Length];
        System.Text.Encoding.ASCII.GetBytes(text, bytes);
        return bytes;
    }

    /// <summary>The builder's text as ASCII bytes, without a string in between (the XML writer escapes everything else).</summary>
    private static byte[] Ascii(System.Text.StringBuilder text)
    {
        var bytes = new byte[text.Length];
        int at = 0;
        foreach (ReadOnlyMemory<char> chunk in text.GetChunks())
        {
            at += System.Text.Encoding.ASCII.GetBytes(chunk.Span, bytes.AsSpan(at));
        }
        return bytes;
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

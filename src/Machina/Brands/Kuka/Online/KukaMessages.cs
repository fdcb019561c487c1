using System.Text;

namespace Machina;

/// <summary>What the KRL driver reports on a new connection (<c>S</c>): its version, where the robot is and its progress.</summary>
/// <param name="Version">Driver version text (<c>VR</c>).</param>
/// <param name="Axes">Axes A1…A6 in degrees.</param>
/// <param name="Position">TCP position in mm (<c>$POS_ACT</c>).</param>
/// <param name="Rotation">TCP orientation, from A, B, C.</param>
/// <param name="Progress">Last executed and last received action ids, or null for a driver that does not report them (1.x).</param>
/// <param name="ModelName">The arm's <c>$MODEL_NAME[]</c> (<c>Model</c>), or null when the driver does not send it.</param>
internal sealed record KukaState(string Version, Joints Axes, Vector Position, Rotation Rotation, DeviceProgress? Progress, string? ModelName = null)
{
    /// <summary>Reads an <c>S</c> element; a protocol error when an attribute is missing or malformed.</summary>
    public static KukaState Parse(KukaElement element)
    {
        string version = element.Attribute("VR") ?? throw new KukaProtocolException("The driver's state has no version (VR).", element.ToString());
        (Joints axes, Vector position, Rotation rotation) = KukaMessages.ReadPose(element);
        DeviceProgress? progress = element.Attribute("Executed") is null && element.Attribute("Received") is null
            ? null
            : new DeviceProgress(element.Integer("Executed"), element.Integer("Received"));
        string? model = element.Attribute("Model") is string name && name.Trim().Length > 0 ? name.Trim() : null;
        return new KukaState(version, axes, position, rotation, progress, model);
    }

    /// <summary>The handshake the online session gets (KUKA robots here have no external axes).</summary>
    /// <remarks>With the arm's <c>$MODEL_NAME[]</c> (driver 2.0 sends it in <c>Model</c>) and the catalogue model it names.</remarks>
    public DeviceHandshake ToHandshake() => new(Version, Position, Rotation, Axes, null, Progress)
    {
        ModelName = ModelName,
        Model = ModelName is null ? null : KukaModelName.Find(ModelName),
    };
}

/// <summary>
/// The XML the KRL driver and monitor send, as Machina's driver writes them (EthernetKRL writes an element as a start and an
/// end tag), and how the host reads poses. Used by the virtual controller; the host reads them with <see cref="KukaXmlReader"/>.
/// </summary>
internal static class KukaMessages
{
    /// <summary><c>&lt;S VR=… A1…A6=… X Y Z A B C=… Executed=… Received=… Model=…&gt;&lt;/S&gt;</c>: sent on every new connection (Model when given).</summary>
    public static string State(Joints axes, Vector position, Rotation rotation, int lastExecutedId, int lastReceivedId, string? modelName = null)
    {
        var sb = new StringBuilder(256);
        KukaXml.AppendAttribute(KukaXml.AppendStart(sb, KukaProtocol.State), "VR", KukaProtocol.DriverVersion);
        AppendPose(sb, axes, position, rotation);
        sb.Append(" Executed=\"").Append(lastExecutedId).Append("\" Received=\"").Append(lastReceivedId).Append('"');
        if (modelName is not null)
        {
            KukaXml.AppendAttribute(sb, "Model", modelName);
        }
        return sb.Append("></S>").ToString();
    }

    /// <summary><c>&lt;R ID="id"&gt;&lt;/R&gt;</c>: the driver executed the action with this id.</summary>
    public static string Acknowledgement(int id) => "<R ID=\"" + Num.I(id) + "\"></R>";

    /// <summary><c>&lt;R ID="…" V="…"&gt;&lt;/R&gt;</c>: the acknowledgement of a read, with the value read.</summary>
    public static string ReadAcknowledgement(int id, double value) => "<R ID=\"" + Num.I(id) + "\" V=\"" + Num.R(value) + "\"></R>";

    /// <summary><c>&lt;P A1…A6=… X Y Z A B C=…&gt;&lt;/P&gt;</c>: a live pose report from the monitor.</summary>
    public static string Pose(Joints axes, Vector position, Rotation rotation)
    {
        var sb = new StringBuilder(200);
        AppendPose(KukaXml.AppendStart(sb, KukaProtocol.Pose), axes, position, rotation);
        return sb.Append("></P>").ToString();
    }

    /// <summary><c>&lt;MON Ms="…"/&gt;</c>: host to monitor, the time between two pose reports in whole milliseconds (at least 1).</summary>
    public static string MonitorRate(double reportsPerSecond) =>
        "<MON Ms=\"" + Num.I(Math.Max(1, (long)Math.Round(1000 / reportsPerSecond))) + "\"/>";

    /// <summary>Reads A1…A6 and X, Y, Z, A, B, C of a state or pose report.</summary>
    public static (Joints Axes, Vector Position, Rotation Rotation) ReadPose(KukaElement element)
    {
        Span<double> a = stackalloc double[Joints.Count];
        for (int i = 0; i < a.Length; i++)
        {
            a[i] = element.Number(KukaProtocol.AxisNames[i]);
        }
        var position = new Vector(element.Number("X"), element.Number("Y"), element.Number("Z"));
        Rotation rotation = KrlFormat.FromAbc(element.Number("A"), element.Number("B"), element.Number("C"));
        return (new Joints(a[0], a[1], a[2], a[3], a[4], a[5]), position, rotation);
    }

    /// <summary>Reads a pose report as a live sample.</summary>
    public static MotionSample ReadSample(KukaElement element)
    {
        (Joints axes, Vector position, Rotation rotation) = ReadPose(element);
        return new MotionSample(position, rotation, axes, null);
    }

    private static void AppendPose(StringBuilder sb, Joints axes, Vector position, Rotation rotation)
    {
        for (int i = 0; i < Joints.Count; i++)
        {
            KukaXml.AppendAttribute(sb, KukaProtocol.AxisNames[i], Math.Round(axes[i], 3));
        }
        (double a, double b, double c) = KrlFormat.Abc(rotation);
        KukaXml.AppendAttribute(sb, "X", Math.Round(position.X, 3));
        KukaXml.AppendAttribute(sb, "Y", Math.Round(position.Y, 3));
        KukaXml.AppendAttribute(sb, "Z", Math.Round(position.Z, 3));
        KukaXml.AppendAttribute(sb, "A", Math.Round(KrlFormat.Degrees(a), 3));
        KukaXml.AppendAttribute(sb, "B", Math.Round(KrlFormat.Degrees(b), 3));
        KukaXml.AppendAttribute(sb, "C", Math.Round(KrlFormat.Degrees(c), 3));
    }
}

using System.Globalization;

namespace Machina.Simulation.Krl;

/// <summary>
/// FRAME elements (<c>&lt;ELEMENT Tag="Robot/Pos" Type="FRAME" /&gt;</c>): received as the attributes X, Y, Z, A, B and C of the element
/// (a component left out is 0) and kept in the element's memory as one value; EKI_SetFrame sets those attributes for EKI_Send.
/// </summary>
internal sealed partial class EkiChannel
{
    /// <summary>The attributes of a FRAME element, in the order of the FRAME type.</summary>
    public static readonly string[] FrameComponents = ["X", "Y", "Z", "A", "B", "C"];

    private HashSet<string>? _frameTags;

    private Dictionary<string, int[]>? _setFlags;

    /// <summary>The flags each RECEIVE tag sets when its element ends (Set_Flag), in the configuration's order.</summary>
    private Dictionary<string, int[]> SetFlags => _setFlags ??= Configuration.Receive.Where(e => e.SetFlag > 0).GroupBy(e => e.Tag, StringComparer.Ordinal)
        .ToDictionary(g => g.Key, g => g.Select(e => e.SetFlag).ToArray(), StringComparer.Ordinal);

    /// <summary>The RECEIVE tags of type FRAME.</summary>
    private HashSet<string> FrameTags => _frameTags ??= [.. Configuration.Receive.Where(e => e.Type == "FRAME").Select(e => e.Tag)];

    /// <summary>
    /// When <paramref name="tag"/> is a component of a FRAME element (<c>Robot/Pos/@X</c>), keeps <paramref name="value"/> in
    /// <paramref name="frames"/> and returns true.
    /// </summary>
    private bool FramePart(Dictionary<string, string[]> frames, string tag, string value)
    {
        if (FrameTags.Count == 0)
        {
            return false;
        }
        int at = tag.LastIndexOf("/@", StringComparison.Ordinal);
        if (at <= 0 || !FrameTags.Contains(tag[..at]))
        {
            return false;
        }
        int index = Array.IndexOf(FrameComponents, tag[(at + 2)..]);
        if (index >= 0)
        {
            if (!frames.TryGetValue(tag[..at], out string[]? parts))
            {
                parts = ["0", "0", "0", "0", "0", "0"];
                frames[tag[..at]] = parts;
            }
            parts[index] = value;
        }
        return true;
    }

    /// <summary>EKI_SetFrame: keeps the components of <paramref name="tag"/> (a SEND element) for the next EKI_Send.</summary>
    public void SetFrame(string tag, IReadOnlyList<double> components)
    {
        if (!Configuration.Send.Contains(tag, StringComparer.Ordinal))
        {
            throw new KrlRuntimeException($"EthernetKRL: the channel {Name} sends no element {tag} (see its SEND configuration)");
        }
        lock (_gate)
        {
            for (int i = 0; i < FrameComponents.Length; i++)
            {
                _toSend[tag + "/@" + FrameComponents[i]] = Format(components[i]);
            }
        }
    }

    /// <summary>The components of a FRAME value as its memory keeps it.</summary>
    public static double[] ParseFrame(string value) =>
        [.. value.Split(' ').Select(p => double.Parse(p, NumberStyles.Float, CultureInfo.InvariantCulture))];
}

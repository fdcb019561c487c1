namespace Machina;

/// <summary>
/// A tool mounted on the robot's flange (a gripper, a pen, an extruder): where its tip is relative to the flange (mm),
/// how the tip frame is turned, its weight (kg) and centre of gravity (mm). Immutable.
/// </summary>
public sealed class Tool : IEquatable<Tool>
{
    private Tool(string name, Vector tcpPosition, Rotation tcpOrientation, double weight, Vector centerOfGravity)
    {
        Name = ValidateName(name);
        TcpPosition = tcpPosition.RequireFinite(nameof(tcpPosition));
        TcpOrientation = tcpOrientation;
        Weight = CheckWeight(weight);
        CenterOfGravity = centerOfGravity.RequireFinite(nameof(centerOfGravity));
    }

    /// <summary>The tool's name; it starts with a letter.</summary>
    public string Name { get; }

    /// <summary>Tool tip position in the flange frame, mm.</summary>
    public Vector TcpPosition { get; }

    /// <summary>Orientation of the tool tip frame relative to the flange.</summary>
    public Rotation TcpOrientation { get; }

    /// <summary>Weight, kg.</summary>
    public double Weight { get; }

    /// <summary>Centre of gravity in the flange frame, mm.</summary>
    public Vector CenterOfGravity { get; }

    /// <summary>A tool weighing 1 kg with its centre of gravity halfway to the tip (as the original assumed).</summary>
    public static Tool Create(string name, Vector tcpPosition, Rotation tcpOrientation) =>
        new(name, tcpPosition, tcpOrientation, 1, tcpPosition * 0.5);

    /// <summary>A tool with all its properties.</summary>
    public static Tool Create(string name, Vector tcpPosition, Rotation tcpOrientation, double weightKg, Vector centerOfGravity) =>
        new(name, tcpPosition, tcpOrientation, Arg.Renamed("weight", nameof(weightKg), weightKg, static w => CheckWeight(w)), centerOfGravity);

    /// <summary>A tool from numbers: tip (mm), tip frame X and Y axes, weight (kg), centre of gravity (mm).</summary>
    public static Tool Create(string name, double tcpX, double tcpY, double tcpZ,
        double tcpXAxisX, double tcpXAxisY, double tcpXAxisZ, double tcpYAxisX, double tcpYAxisY, double tcpYAxisZ,
        double weightKg, double cogX, double cogY, double cogZ) =>
        new(name, Arg.Vector(tcpX, tcpY, tcpZ),
            Arg.FromAxes(Arg.Vector(tcpXAxisX, tcpXAxisY, tcpXAxisZ), Arg.Vector(tcpYAxisX, tcpYAxisY, tcpYAxisZ), nameof(tcpXAxisX), nameof(tcpYAxisX)),
            Arg.Renamed("weight", nameof(weightKg), weightKg, static w => CheckWeight(w)), Arg.Vector(cogX, cogY, cogZ));

    /// <summary>The weight (kg) when it is a finite number of 0 or more; otherwise an <see cref="ArgumentException"/> for "weight".</summary>
    internal static double CheckWeight(double weight)
    {
        Num.Finite(weight, nameof(weight));
        if (weight < 0)
        {
            throw new ArgumentException($"Tool weight cannot be negative, but it was {Num.G(weight)} kg.", nameof(weight));
        }
        return weight;
    }

    /// <summary>Refuses names that are empty or do not start with a letter, or that contain characters other than letters, digits and '_'.</summary>
    internal static string ValidateName(string? name)
    {
        if (string.IsNullOrEmpty(name) || !char.IsLetter(name[0]))
        {
            throw new ArgumentException($"\"{name}\" is not a valid tool name: it must start with a letter.", nameof(name));
        }
        foreach (char c in name)
        {
            if (!(char.IsLetterOrDigit(c) || c == '_'))
            {
                throw new ArgumentException($"\"{name}\" is not a valid tool name: use only letters, digits and '_'.", nameof(name));
            }
        }
        return name;
    }

    /// <summary>The instruction that defines this tool: <c>DefineTool("name",x,y,z,Xx,Xy,Xz,Yx,Yy,Yz,weight,cx,cy,cz);</c>.</summary>
    public string ToDefineInstruction()
    {
        Vector t = TcpPosition, x = InstructionText.Axis(TcpOrientation.XAxis), y = InstructionText.Axis(TcpOrientation.YAxis), c = CenterOfGravity;
        return InstructionText.Call("DefineTool", InstructionText.Quote(Name), [t.X, t.Y, t.Z, x.X, x.Y, x.Z, y.X, y.Y, y.Z, Weight, c.X, c.Y, c.Z], null);
    }

    /// <summary>Text such as <c>Tool["pen", Tip[0,0,50], Orientation[[1, 0, 0], [0, 1, 0], [0, 0, 1]], 1 kg]</c>.</summary>
    public override string ToString() =>
        $"Tool[\"{Name}\", Tip{(Point)TcpPosition}, Orientation{TcpOrientation.ToOrientationString()}, {Num.G(Weight)} kg]";

    /// <summary>Same name, tip, weight and centre of gravity, and tip frames within 1e-9 degrees.</summary>
    public bool Equals(Tool? other) =>
        other is not null && Name == other.Name && TcpPosition == other.TcpPosition && Weight == other.Weight
        && CenterOfGravity == other.CenterOfGravity && TcpOrientation.IsSimilar(other.TcpOrientation, 1e-9);

    /// <inheritdoc/>
    public override bool Equals(object? obj) => Equals(obj as Tool);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Name, TcpPosition, Weight);
}

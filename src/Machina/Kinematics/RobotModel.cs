namespace Machina;

/// <summary>
/// An immutable description of one robot arm: its name, brand, geometry, joint limits and (where published) maximum joint speeds,
/// with the public documents the numbers come from. Use <see cref="RobotModels"/> for the built-in catalogue or
/// <see cref="FromOpw"/> / <see cref="FromUniversalRobotsDh"/> / <see cref="FromDh"/> to define your own.
/// </summary>
public sealed class RobotModel
{
    private RobotModel(string name, string brand, KinematicFamily family, Joints min, Joints max, Joints? maxSpeeds, string source)
    {
        Name = name;
        Brand = brand;
        Family = family;
        MinJoints = min;
        MaxJoints = max;
        MaxJointSpeeds = maxSpeeds;
        Source = source;
        Kinematics = null!;
    }

    /// <summary>Model name, e.g. <c>IRB 120</c> or <c>UR5e</c>.</summary>
    public string Name { get; }

    /// <summary>Brand whose joint conventions apply: <c>ABB</c>, <c>KUKA</c> or <c>UR</c>.</summary>
    public string Brand { get; }

    /// <summary>Geometry family (which solver is used).</summary>
    public KinematicFamily Family { get; }

    /// <summary>The OPW lengths (mm) for <see cref="KinematicFamily.Opw"/> models, otherwise null.</summary>
    public OpwParameters? Opw { get; private init; }

    /// <summary>The UR DH lengths (mm) for <see cref="KinematicFamily.UniversalRobots"/> models, otherwise null.</summary>
    public UniversalRobotsDh? UniversalRobotsDh { get; private init; }

    /// <summary>Lowest allowed value of each joint, degrees.</summary>
    public Joints MinJoints { get; }

    /// <summary>Highest allowed value of each joint, degrees.</summary>
    public Joints MaxJoints { get; }

    /// <summary>Maximum speed of each joint in degrees per second, or null when not published.</summary>
    public Joints? MaxJointSpeeds { get; }

    /// <summary>The public documents the numbers come from.</summary>
    public string Source { get; }

    /// <summary>Forward and inverse kinematics for this model.</summary>
    public IKinematics Kinematics { get; private set; }

    /// <summary>
    /// A user-defined ABB or KUKA style arm from its seven OPW lengths (mm) and joint limits (degrees). Joint values then follow
    /// that brand's conventions (see docs/kinematics.md).
    /// </summary>
    public static RobotModel FromOpw(string name, string brand, OpwParameters parameters, Joints minJoints, Joints maxJoints, Joints? maxJointSpeeds = null, string source = "user defined")
    {
        string b = CheckCommon(name, brand, minJoints, maxJoints, maxJointSpeeds, source);
        if (BrandRegistry.Find(b) is not { Family: KinematicFamily.Opw } opwBrand)
        {
            throw new ArgumentException($"OPW models follow ABB or KUKA joint conventions; brand must be \"ABB\" or \"KUKA\", not \"{brand}\".", nameof(brand));
        }
        parameters.Validate();
        var model = new RobotModel(name, b, KinematicFamily.Opw, minJoints, maxJoints, maxJointSpeeds, source) { Opw = parameters };
        model.Kinematics = new OpwKinematics(model, parameters, opwBrand.MirroredOpwJoints);
        return model;
    }

    /// <summary>A user-defined Universal Robots style arm from its DH lengths (mm, UR signs) and joint limits (degrees).</summary>
    public static RobotModel FromUniversalRobotsDh(string name, UniversalRobotsDh parameters, Joints minJoints, Joints maxJoints, Joints? maxJointSpeeds = null, string source = "user defined")
    {
        string brand = BrandRegistry.All.First(b => b.Family == KinematicFamily.UniversalRobots).ModelBrand!;
        CheckCommon(name, brand, minJoints, maxJoints, maxJointSpeeds, source);
        parameters.Validate();
        var model = new RobotModel(name, brand, KinematicFamily.UniversalRobots, minJoints, maxJoints, maxJointSpeeds, source) { UniversalRobotsDh = parameters };
        model.Kinematics = new UniversalRobotsKinematics(model, parameters);
        return model;
    }

    /// <summary>
    /// Any six-joint serial arm from its Denavit–Hartenberg table: six rows (lengths in mm, angles in degrees), standard or modified
    /// convention, joint limits (degrees) and, optionally, maximum joint speeds (°/s) and where the flange sits in the last DH frame
    /// (default: the last frame itself). Joint values are the table's θ minus each row's offset. The inverse is numerical (see
    /// docs/kinematics.md): slower than the built-in OPW and UR solvers, and it lists the solutions it finds (up to eight).
    /// </summary>
    public static RobotModel FromDh(string name, string brand, DhConvention convention, IReadOnlyList<DhJoint> joints, Joints minJoints, Joints maxJoints,
        Joints? maxJointSpeeds = null, Pose? flange = null, string source = "user defined")
    {
        string b = CheckCommon(name, brand, minJoints, maxJoints, maxJointSpeeds, source);
        ArgumentNullException.ThrowIfNull(joints);
        if (joints.Count != Joints.Count)
        {
            throw new ArgumentException($"A DH table for \"{name}\" needs exactly six rows, one per joint (got {joints.Count}).", nameof(joints));
        }
        if (!Enum.IsDefined(convention))
        {
            throw new ArgumentOutOfRangeException(nameof(convention), convention, "The DH convention is Standard or Modified.");
        }
        DhJoint[] table = [.. joints];
        for (int i = 0; i < table.Length; i++)
        {
            DhJoint j = table[i];
            if (!(double.IsFinite(j.A) && double.IsFinite(j.Alpha) && double.IsFinite(j.D) && double.IsFinite(j.ThetaOffset)))
            {
                throw new ArgumentException($"Row {i + 1} of the DH table of \"{name}\" has a value that is not a finite number.", nameof(joints));
            }
        }
        Pose f = flange ?? Pose.Identity;
        f.Position.RequireFinite(nameof(flange));
        var model = new RobotModel(name, b, KinematicFamily.Dh, minJoints, maxJoints, maxJointSpeeds, source);
        model.Kinematics = new DhKinematics(model, convention, table, f);
        return model;
    }

    private static string CheckCommon(string name, string brand, Joints min, Joints max, Joints? speeds, string source)
    {
        if (string.IsNullOrWhiteSpace(name))
        {
            throw new ArgumentException("A robot model needs a name.", nameof(name));
        }
        ArgumentNullException.ThrowIfNull(brand);
        ArgumentNullException.ThrowIfNull(source);
        min.RequireFinite(nameof(min));
        max.RequireFinite(nameof(max));
        for (int i = 0; i < Joints.Count; i++)
        {
            if (!(min[i] < max[i]))
            {
                throw new ArgumentException($"Joint {i + 1} of \"{name}\": the minimum ({Num.G(min[i])}°) must be below the maximum ({Num.G(max[i])}°).");
            }
            if (speeds is Joints s && !(s[i] > 0 && double.IsFinite(s[i])))
            {
                throw new ArgumentException($"Joint {i + 1} of \"{name}\": the maximum speed must be a positive number of degrees per second, not {Num.G(s[i])}.");
            }
        }
        // A brand's alias (e.g. "Universal Robots") becomes its catalogue name; other brands are kept, in capitals.
        return BrandRegistry.Find(brand)?.ModelBrand ?? brand.Trim().ToUpperInvariant();
    }

    /// <summary>
    /// Where the arm's joints are for these joint values (mm, base frame), from the base to the flange: the points to join with
    /// lines to draw the arm. The last point is the flange (<c>Kinematics.Forward(joints).Position</c>).
    /// </summary>
    /// <exception cref="ArgumentException">A joint value is not a finite number.</exception>
    public IReadOnlyList<Vector> LinkPositions(Joints joints) => Kinematics switch
    {
        OpwKinematics opw => opw.LinkPoints(joints),
        UniversalRobotsKinematics ur => ur.LinkPoints(joints),
        DhKinematics dh => dh.LinkPoints(joints),
        IKinematics other => [Vector.Zero, other.Forward(joints).Position],
    };

    /// <summary>True when every joint is within this model's limits.</summary>
    public bool IsWithinLimits(Joints joints) => KinematicsCore.IsWithinLimits(this, joints);

    /// <summary>Text such as <c>ABB IRB 120</c>.</summary>
    public override string ToString() => $"{Brand} {Name}";
}

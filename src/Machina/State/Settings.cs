namespace Machina;

/// <summary>The motion settings that <c>PushSettings</c> saves and <c>PopSettings</c> restores.</summary>
/// <param name="Speed">Speed, mm/s.</param>
/// <param name="Acceleration">Acceleration, mm/s².</param>
/// <param name="Precision">Blend radius, mm.</param>
/// <param name="MotionType">Linear or joint motion.</param>
/// <param name="ReferenceCS">Frame of relative actions.</param>
/// <param name="ExtrusionRate">Extrusion rate, mm of filament per mm of travel.</param>
public readonly record struct Settings(double Speed, double Acceleration, double Precision, MotionType MotionType, ReferenceCS ReferenceCS, double ExtrusionRate)
{
    /// <summary>The settings of a new robot: 20 mm/s, 30 mm/s², 5 mm, linear, world, no extrusion.</summary>
    public static Settings Default => new(20, 30, 5, MotionType.Linear, ReferenceCS.World, 0);

    /// <summary>
    /// True for 0 and the built-in 30 mm/s²: compilers leave these to the controller's own acceleration (written as 0.03 m/s²
    /// the built-in value made the original's UR programs crawl, spec bug 34).
    /// </summary>
    internal static bool MeansControllerAcceleration(double acceleration) => acceleration == 0 || acceleration == Default.Acceleration;

    /// <summary>
    /// Text such as <c>speed 20 mm/s, acceleration 30 mm/s², precision 5 mm, linear motion, world frame</c> (and the extrusion rate
    /// when there is one).
    /// </summary>
    public override string ToString() =>
        $"speed {Num.G(Speed)} mm/s, acceleration {Num.G(Acceleration)} mm/s², precision {Num.G(Precision)} mm, " +
        $"{MotionType.ToString().ToLowerInvariant()} motion, {ReferenceCS.ToString().ToLowerInvariant()} frame" +
        (ExtrusionRate == 0 ? "" : $", extrusion {Num.G(ExtrusionRate)} mm/mm");
}

namespace Machina;

/// <summary>
/// Everything Machina knows about one brand, in one place: its names, its compiler, its online support, its driver files and the
/// arm its virtual controller moves like. Each brand declares one in its own folder (e.g. <c>Brands/Abb/AbbBrand.cs</c>) and
/// <see cref="BrandRegistry"/> lists them; every other part of Machina (compilers, online control, command line, bridge,
/// virtual controllers) reads the registry instead of naming a brand.
/// </summary>
/// <param name="Type">The brand's value in <see cref="RobotType"/>.</param>
/// <param name="Name">The brand's name as typed on the command line, in lower case (e.g. "abb").</param>
/// <param name="Kind">Arm, printer or listing.</param>
/// <param name="CreateCompiler">Makes a new compiler for the brand's language.</param>
internal sealed record BrandDefinition(RobotType Type, string Name, BrandKind Kind, Func<Compiler> CreateCompiler)
{
    /// <summary>Other names a user may type for the brand (any letter case), e.g. "universal robots".</summary>
    internal IReadOnlyList<string> Aliases { get; init; } = [];

    /// <summary>The brand's online support, or null when it is compiled only.</summary>
    internal IOnlineBrand? Online { get; init; }

    /// <summary>The brand as the model catalogue writes it (<see cref="RobotModel.Brand"/>, e.g. "ABB"); null when it takes no arm model.</summary>
    internal string? ModelBrand { get; init; }

    /// <summary>The brand's arms in the built-in catalogue (<see cref="RobotModels"/>), made when the catalogue is first read; none by default.</summary>
    internal Func<IEnumerable<RobotModel>> Models { get; init; } = () => [];

    /// <summary>The joint layout of the brand's arms (OPW for ABB and KUKA, Universal Robots for UR); null for a device that is not an arm.</summary>
    internal KinematicFamily? Family { get; init; }

    /// <summary>True when the brand counts joints 1, 4 and 6 the other way round from ABB (KUKA's convention, docs/kinematics.md).</summary>
    internal bool MirroredOpwJoints { get; init; }

    /// <summary>The catalogue name of the arm the brand's virtual controller moves like when no model is given (e.g. "IRB 120").</summary>
    internal string? DefaultModel { get; init; }

    /// <summary>The port the brand's driver usually listens on (ABB and KUKA: Machina's driver; UR: the robot's script port); 0 when none.</summary>
    internal int DefaultPort { get; init; }

    /// <summary>True when the brand's driver is a client that connects back to the computer (UR's script); false when it listens on the controller.</summary>
    internal bool DriverConnectsBack { get; init; }

    /// <summary>What a user does with the driver files once written, given their count, the host and the port; null when the brand has no driver.</summary>
    internal Func<int, string, int, string>? DriverNextSteps { get; init; }

    /// <summary>
    /// Installs and starts Machina's driver on a controller of the brand (host, port, how to reach its web services, the log), for
    /// <c>Robot.InstallDriverAsync</c> and <c>ConnectionManager("machina")</c>; null when Machina does not install the brand's driver.
    /// </summary>
    internal Func<string, int, RobotWebServicesOptions, RobotLogger, CancellationToken, Task>? InstallDriver { get; init; }

    /// <summary>The name of the instruction a driver request of this brand carries (e.g. "MoveL"), or null when it is not recognised.</summary>
    internal Func<string, string?> InstructionName { get; init; } = _ => null;

    /// <summary>How the brand's controller times a motion, for cycle-time estimates (<see cref="MotionTiming.Generic"/> unless the brand knows better).</summary>
    internal MotionTiming Timing { get; init; } = MotionTiming.Generic;

    /// <summary>The brand as Machina writes it in messages (e.g. "ABB", "UR").</summary>
    internal string DisplayName => Type.ToString();

    /// <summary>True for an industrial arm (it takes an arm model).</summary>
    internal bool IsArm => Kind == BrandKind.Arm;

    /// <summary>True when <paramref name="text"/> is this brand's name or one of its aliases (any letter case, spaces around ignored).</summary>
    internal bool IsNamed(string text)
    {
        string t = text.Trim();
        return string.Equals(t, Name, StringComparison.OrdinalIgnoreCase) || Aliases.Any(a => string.Equals(t, a, StringComparison.OrdinalIgnoreCase));
    }
}

namespace Machina;

/// <summary>Which link and which controller-side programs each brand uses online.</summary>
internal static class OnlineDrivers
{
    /// <summary>A factory of links for a robot, or an exception when its brand cannot be controlled online yet.</summary>
    internal static Func<IDeviceDriver> For(Robot robot) => robot.Brand switch
    {
        RobotType.ABB => () => new AbbDriver(robot.Logger),
        RobotType.UR or RobotType.KUKA => throw new NotSupportedException(
            $"Online control of {robot.Brand} robots is not available in this version yet; only ABB robots can go online."),
        _ => throw new ArgumentException($"{robot.Brand} robots cannot be controlled online; only ABB, UR and KUKA robots can.", nameof(robot)),
    };

    /// <summary>The driver files of a brand with HOSTNAME and PORT filled in, by file name.</summary>
    internal static IReadOnlyDictionary<string, string> Modules(RobotType brand, IReadOnlyDictionary<string, string> parameters) => brand switch
    {
        _ => throw new NotSupportedException($"Machina has no driver modules for {brand} robots in this version."),
    };
}

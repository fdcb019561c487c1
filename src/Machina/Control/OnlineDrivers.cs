namespace Machina;

/// <summary>Which link and which controller-side programs each brand uses online.</summary>
internal static class OnlineDrivers
{
    /// <summary>A factory of links for a robot, or an exception when its brand cannot be controlled online yet.</summary>
    internal static Func<IDeviceDriver> For(Robot robot) => robot.Brand switch
    {
        RobotType.ABB => () => new AbbDriver(robot.Logger, robot.Time),
        RobotType.UR or RobotType.KUKA => throw new NotSupportedException(
            $"Online control of {robot.Brand} robots is not available in this version yet; only ABB robots can go online."),
        _ => throw new ArgumentException($"{robot.Brand} robots cannot be controlled online; only ABB, UR and KUKA robots can.", nameof(robot)),
    };

    /// <summary>The driver files of a brand with HOSTNAME and PORT filled in, by file name.</summary>
    internal static IReadOnlyDictionary<string, string> Modules(RobotType brand, IReadOnlyDictionary<string, string> parameters) => brand switch
    {
        RobotType.ABB => AbbDriverModules.Create(Require(parameters, "HOSTNAME"), Port(parameters), MonitorRate(parameters)),
        _ => throw new NotSupportedException($"Machina has no driver modules for {brand} robots in this version."),
    };

    private static string Require(IReadOnlyDictionary<string, string> parameters, string key) =>
        parameters.TryGetValue(key, out string? value) && !string.IsNullOrWhiteSpace(value)
            ? value.Trim()
            : throw new ArgumentException($"The driver modules need \"{key}\" (HOSTNAME: the address the driver listens on, PORT: its port).", nameof(parameters));

    private static int Port(IReadOnlyDictionary<string, string> parameters)
    {
        string text = Require(parameters, "PORT");
        return int.TryParse(text, System.Globalization.NumberStyles.None, Num.Inv, out int port)
            ? port
            : throw new ArgumentException($"PORT must be a whole number, not \"{text}\".", nameof(parameters));
    }

    private static double MonitorRate(IReadOnlyDictionary<string, string> parameters)
    {
        if (!parameters.TryGetValue("MONITOR_RATE", out string? text))
        {
            return AbbDriverModules.DefaultMonitorRate;
        }
        return double.TryParse(text, System.Globalization.NumberStyles.Float, Num.Inv, out double rate)
            ? rate
            : throw new ArgumentException($"MONITOR_RATE must be a number of reports per second, not \"{text}\".", nameof(parameters));
    }
}

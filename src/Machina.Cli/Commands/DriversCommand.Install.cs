using System.Globalization;

namespace Machina.Cli.Commands;

/// <summary><c>machina drivers abb --install</c>: installs and starts the driver through the controller's Robot Web Services.</summary>
internal static partial class DriversCommand
{
    private static async Task<int> InstallAsync(RobotType brand, string host, CliArgs args, CliContext context)
    {
        if (BrandRegistry.For(brand).InstallDriver is null)
        {
            string installable = string.Join(" and ", BrandRegistry.Online.Where(b => b.InstallDriver is not null).Select(b => b.DisplayName));
            throw new UsageException($"machina drivers --install works on {installable} controllers only (through Robot Web Services), not {brand}. See: machina drivers --help");
        }
        int port = args.Port("--port", 7000);
        int rwsPort = args.Port("--rws-port", 80);
        double maxRatio = args.Positive("--max-speed-ratio", 100);
        if (maxRatio > 100)
        {
            throw new UsageException("--max-speed-ratio is a percentage, at most 100. See: machina drivers --help");
        }
        var bot = Robot.Create("Installer", brand);
        bot.WebServices = new RobotWebServicesOptions
        {
            Port = rwsPort,
            UserName = args.Value("--user") ?? "Default User",
            Password = Environment.GetEnvironmentVariable("MACHINA_RWS_PASSWORD") ?? "robotics",
            MaxSpeedRatio = (int)Math.Floor(maxRatio),
        };
        using IDisposable log = bot.Logger.AddSink(e => context.Stderr.WriteLine(e.Message), LogLevel.INFO);
        try
        {
            await bot.InstallDriverAsync(host, port, context.Cancellation).ConfigureAwait(false);
        }
        catch (RobotWebServicesException ex)
        {
            throw new CliException(ex.Message);
        }
        string address = host + ":" + port.ToString(CultureInfo.InvariantCulture);
        await context.Stderr.WriteLineAsync($"The driver runs on the controller and listens on {address}. Then: machina run PROGRAM --brand abb --host {host} --port {port.ToString(CultureInfo.InvariantCulture)}").ConfigureAwait(false);
        return ExitCodes.Ok;
    }
}

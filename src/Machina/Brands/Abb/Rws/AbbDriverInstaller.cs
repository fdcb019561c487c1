using System.Globalization;

namespace Machina;

/// <summary>
/// Installs Machina's RAPID driver and monitor on an ABB controller through Robot Web Services, as the original's "Machina"
/// connection mode did through the PC SDK: checks that it is safe to start (automatic mode, motors on, speed ratio, nobody else
/// holding mastership), uploads the filled modules to <c>$HOME</c>, loads them into their tasks, resets the program pointer and
/// starts execution.
/// </summary>
internal static class AbbDriverInstaller
{
    /// <summary>The motion task the driver is loaded into.</summary>
    public const string MotionTask = "T_ROB1";

    /// <summary>The task the monitor is loaded into, when the controller has it (the Multitasking option, configured by the user).</summary>
    public const string MonitorTask = "T_MACHINA_MONITOR";

    /// <summary>The name of the driver's module (MODULE Machina_Driver in drivers/abb).</summary>
    public const string DriverModule = "Machina_Driver";

    /// <summary>
    /// Installs and starts the driver on the controller at <paramref name="host"/> through its Robot Web Services (<see cref="AbbBrand"/>'s
    /// <see cref="BrandDefinition.InstallDriver"/>), listening on <paramref name="port"/>.
    /// </summary>
    public static async Task InstallAsync(string host, int port, RobotWebServicesOptions options, RobotLogger log, CancellationToken cancellationToken)
    {
        using var client = new RwsClient(host, options);
        log.Info($"Installing the driver on {client.Address} (Robot Web Services {(options.UseRws2 ? "2.0" : "1.0")}).");
        await InstallAsync(client, host, port, options, log, cancellationToken).ConfigureAwait(false);
    }

    /// <summary>
    /// Installs and starts the driver listening on <paramref name="host"/>:<paramref name="port"/> (the monitor on port + 1),
    /// logging each step; throws <see cref="RobotWebServicesException"/> with the reason when a check or a step fails.
    /// </summary>
    public static async Task InstallAsync(RwsClient client, string host, int port, RobotWebServicesOptions options, RobotLogger log,
        CancellationToken cancellationToken)
    {
        IReadOnlyDictionary<string, string> modules = AbbDriverModules.Create(host, port);
        if (await IsRunningAsync(client, host, port, modules["machina_abb_driver.mod"], cancellationToken).ConfigureAwait(false))
        {
            // A reconnection: the running driver holds the actions it was given and reports its progress; reinstalling would lose them.
            log.Info($"Machina's driver already runs on the controller, listening on {host}:{port}: it is left running, not installed again.");
            return;
        }
        await CheckSafeToStartAsync(client, options, log, cancellationToken).ConfigureAwait(false);
        IReadOnlyList<string> tasks = await client.GetTasksAsync(cancellationToken).ConfigureAwait(false);
        string motionTask = tasks.Contains(MotionTask, StringComparer.OrdinalIgnoreCase) ? MotionTask
            : tasks.FirstOrDefault() ?? throw Refused("the controller has no RAPID task.");
        bool monitor = tasks.Contains(MonitorTask, StringComparer.OrdinalIgnoreCase);
        if (!monitor)
        {
            log.Warning($"The controller has no task {MonitorTask}: the driver runs without its monitor (no MotionUpdate events). " +
                "See docs/rws.md to add the task.");
        }
        await client.RequestMastershipAsync(cancellationToken).ConfigureAwait(false);
        try
        {
            if (await client.GetExecutionStateAsync(cancellationToken).ConfigureAwait(false) == "running")
            {
                log.Warning("RAPID was running on the controller; Machina stops it to load its driver.");
                await client.StopAsync(cancellationToken).ConfigureAwait(false);
            }
            await LoadAsync(client, "machina_abb_driver.mod", modules, motionTask, log, cancellationToken).ConfigureAwait(false);
            if (monitor)
            {
                await LoadAsync(client, "machina_abb_monitor.mod", modules, MonitorTask, log, cancellationToken).ConfigureAwait(false);
            }
            await client.ResetProgramPointerAsync(cancellationToken).ConfigureAwait(false);
            log.Info("The program pointer is at main.");
            await client.StartAsync(cancellationToken).ConfigureAwait(false);
            log.Info($"RAPID started: the driver listens on {host}:{port}.");
        }
        finally
        {
            await ReleaseQuietlyAsync(client, log).ConfigureAwait(false);
        }
    }

    /// <summary>True when RAPID runs and T_ROB1 holds this very driver (same version, address and port).</summary>
    private static async Task<bool> IsRunningAsync(RwsClient client, string host, int port, string driver, CancellationToken cancellationToken)
    {
        if (await client.GetExecutionStateAsync(cancellationToken).ConfigureAwait(false) != "running")
        {
            return false;
        }
        try
        {
            foreach (string name in new[] { "DRIVER_VERSION_MAJOR", "DRIVER_VERSION_MINOR", "DRIVER_VERSION_PATCH" })
            {
                string value = await client.GetSymbolAsync(MotionTask, DriverModule, name, cancellationToken).ConfigureAwait(false);
                if (!driver.Contains($"CONST string {name} := {value};", StringComparison.Ordinal))
                {
                    return false;
                }
            }
            return await client.GetSymbolAsync(MotionTask, DriverModule, "SERVER_IP", cancellationToken).ConfigureAwait(false) == $"\"{host}\""
                && await client.GetSymbolAsync(MotionTask, DriverModule, "SERVER_PORT", cancellationToken).ConfigureAwait(false) == port.ToString(CultureInfo.InvariantCulture);
        }
        catch (RobotWebServicesException ex) when (ex.HttpStatus is 400 or 404)
        {
            return false; // the task runs something else
        }
    }

    private static async Task CheckSafeToStartAsync(RwsClient client, RobotWebServicesOptions options, RobotLogger log, CancellationToken cancellationToken)
    {
        string mode = await client.GetOperationModeAsync(cancellationToken).ConfigureAwait(false);
        if (!mode.Equals("AUTO", StringComparison.OrdinalIgnoreCase))
        {
            throw Refused($"the controller is in {ModeName(mode)} mode ({mode}); Machina starts its driver only in automatic mode (AUTO). " +
                "Turn the mode switch to automatic and confirm it on the FlexPendant, then connect again.");
        }
        string state = await client.GetControllerStateAsync(cancellationToken).ConfigureAwait(false);
        if (!state.Equals("motoron", StringComparison.OrdinalIgnoreCase))
        {
            throw Refused($"the motors are not on (the controller state is {state}). Make sure the cell is clear, press Motors On, then connect again.");
        }
        int ratio = await client.GetSpeedRatioAsync(cancellationToken).ConfigureAwait(false);
        if (ratio > options.MaxSpeedRatio)
        {
            throw Refused($"the speed ratio is {ratio} %, above the {options.MaxSpeedRatio} % allowed by RobotWebServicesOptions.MaxSpeedRatio. " +
                "Lower it on the FlexPendant (or raise MaxSpeedRatio if this speed is intended), then connect again.");
        }
        log.Info($"The controller is in automatic mode, motors on, speed ratio {ratio} %.");
    }

    private static async Task LoadAsync(RwsClient client, string file, IReadOnlyDictionary<string, string> modules, string task, RobotLogger log,
        CancellationToken cancellationToken)
    {
        string path = "$HOME/" + file;
        await client.UploadFileAsync(path, modules[file], cancellationToken).ConfigureAwait(false);
        await client.LoadModuleAsync(task, path, replace: true, cancellationToken).ConfigureAwait(false);
        log.Info($"Loaded {path} into {task}.");
    }

    private static async Task ReleaseQuietlyAsync(RwsClient client, RobotLogger log)
    {
        try
        {
            using var release = new CancellationTokenSource(TimeSpan.FromSeconds(5));
            await client.ReleaseMastershipAsync(release.Token).ConfigureAwait(false);
        }
        catch (Exception ex) when (ex is RobotWebServicesException or OperationCanceledException)
        {
            log.Warning($"Could not release mastership of the controller: {ex.Message}");
        }
    }

    private static string ModeName(string mode) => mode.ToUpperInvariant() switch
    {
        "MANR" => "manual reduced-speed",
        "MANF" => "manual full-speed",
        _ => "a non-automatic",
    };

    private static RobotWebServicesException Refused(string reason) =>
        new("Machina did not install its driver: " + reason, 0, null);
}

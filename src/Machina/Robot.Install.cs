namespace Machina;

public sealed partial class Robot
{
    private bool _installsDriver;

    /// <summary>
    /// How Machina reaches the ABB controller's Robot Web Services to install its driver (port, user, RWS version, the largest
    /// speed ratio it accepts); used by <see cref="InstallDriverAsync"/> and by <c>ConnectionManager("machina")</c>.
    /// </summary>
    public RobotWebServicesOptions WebServices { get; set; } = new();

    /// <summary>Sets the controller user (and password) Machina logs in with to install its driver; the original's SetUser.</summary>
    /// <returns>True.</returns>
    public bool SetUser(string name, string password)
    {
        ArgumentException.ThrowIfNullOrEmpty(name);
        ArgumentNullException.ThrowIfNull(password);
        RobotWebServicesOptions o = WebServices;
        WebServices = new RobotWebServicesOptions
        {
            Port = o.Port, UseRws2 = o.UseRws2, MaxSpeedRatio = o.MaxSpeedRatio, Timeout = o.Timeout, UserName = name, Password = password,
        };
        return true;
    }

    /// <summary>
    /// Installs Machina's driver on the ABB controller at <paramref name="host"/> through its Robot Web Services and starts it,
    /// listening on <paramref name="port"/> (the monitor on port + 1): checks that the controller is in automatic mode with the
    /// motors on and a speed ratio at most <see cref="RobotWebServicesOptions.MaxSpeedRatio"/>, takes mastership, uploads the
    /// modules to $HOME, loads them into T_ROB1 (and T_MACHINA_MONITOR when the controller has it), resets the program pointer
    /// and starts RAPID. Then <see cref="ConnectAsync"/> connects as usual. See docs/rws.md.
    /// </summary>
    /// <exception cref="RobotWebServicesException">A check failed or the controller refused a step; the message says why.</exception>
    /// <exception cref="NotSupportedException">The robot is not an ABB.</exception>
    public async Task InstallDriverAsync(string host, int port = 7000, CancellationToken cancellationToken = default)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(host);
        ThrowIfDisposed("install the driver");
        if (BrandRegistry.For(Brand).InstallDriver is not { } install)
        {
            string installable = string.Join(" and ", BrandRegistry.All.Where(b => b.InstallDriver is not null).Select(b => b.DisplayName));
            throw new NotSupportedException($"Machina installs its driver through Robot Web Services on {installable} controllers only; this robot is a {Brand}.");
        }
        await install(host, port, WebServices, Logger, cancellationToken).ConfigureAwait(false);
    }
}

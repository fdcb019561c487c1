namespace Machina;

/// <summary>
/// How Machina reaches an ABB controller's Robot Web Services to install and start its driver (see
/// <see cref="Robot.InstallDriverAsync"/>): the port, the user, the RWS version and the largest speed ratio it accepts.
/// </summary>
public sealed class RobotWebServicesOptions
{
    /// <summary>The HTTP port; null for the usual one (80 for RWS 1.0 on IRC5, 443 for RWS 2.0 on OmniCore).</summary>
    public int? Port { get; init; }

    /// <summary>The controller user (ABB's default user, "Default User", unless changed).</summary>
    public string UserName { get; init; } = "Default User";

    /// <summary>The user's password (the default user's, "robotics", unless changed).</summary>
    public string Password { get; init; } = "robotics";

    /// <summary>True for RWS 2.0 (OmniCore, RobotWare 7: HTTPS and basic authentication); false for RWS 1.0 (IRC5, RobotWare 6: HTTP and digest).</summary>
    public bool UseRws2 { get; init; }

    /// <summary>
    /// The largest speed ratio (the FlexPendant's speed override, in percent) at which Machina starts the driver (default 100):
    /// set it lower to refuse to start a robot that would run faster than you expect.
    /// </summary>
    public int MaxSpeedRatio { get; init; } = 100;

    /// <summary>RWS 2.0 over plain HTTP: only for the RAPID twin in tests (the twin serves no TLS); never for a controller.</summary>
    internal bool Rws2OverHttp { get; init; }

    /// <summary>
    /// The largest answer read, in bytes (16 MiB; Robot Web Services answers are a few kilobytes): a larger one is refused with a
    /// <see cref="RobotWebServicesException"/> before it fills the memory. Internal: a test sets it lower.
    /// </summary>
    internal long MaxAnswerBytes { get; init; } = 16 * 1024 * 1024;

    /// <summary>How long one request to the controller may take, its answer read (default 10 s).</summary>
    public TimeSpan Timeout { get; init; } = TimeSpan.FromSeconds(10);
}

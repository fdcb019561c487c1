namespace Machina;

/// <summary>
/// The version of its controller-side driver (drivers/&lt;brand&gt;) a brand's host needs, checked on every connection
/// before anything is sent. The driver reports its version in its handshake; one of another major version, or older than
/// <see cref="Required"/>'s minor version, speaks another protocol (another wire resolution, requests it lacks) and is refused
/// with both versions and what to do, never misread.
/// </summary>
/// <param name="Brand">The brand as users write it ("ABB").</param>
/// <param name="Required">The version of the driver this Machina ships (major.minor.patch).</param>
/// <param name="Remedy">What to do when the controller runs another driver: a sentence or two.</param>
internal sealed record DriverRequirement(string Brand, Version Required, string Remedy)
{
    /// <summary>True when a driver of version <paramref name="installed"/> speaks this host's protocol: the same major version, at least the minor.</summary>
    public bool Accepts(Version installed) => installed.Major == Required.Major && installed.Minor >= Required.Minor;

    /// <summary>
    /// Throws <see cref="RobotConnectionException"/> naming <paramref name="installed"/> (the version the driver reported) and
    /// <see cref="Required"/> unless <see cref="Accepts"/> takes it.
    /// </summary>
    public void Check(string installed)
    {
        if (!Version.TryParse(installed, out Version? version) || !Accepts(version))
        {
            throw new RobotConnectionException(Refusal(installed));
        }
    }

    /// <summary>The refusal of a driver that reported <paramref name="installed"/>.</summary>
    public string Refusal(string installed) =>
        $"The Machina driver on the {Brand} controller is version {(installed.Length == 0 ? "(none reported)" : installed)}; this Machina needs driver {Required} " +
        $"({Required.Major}.{Required.Minor} or a later {Required.Major}.x), and speaks no other. {Remedy}";
}

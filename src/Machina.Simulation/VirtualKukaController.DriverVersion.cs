namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// A driver file as the driver of <paramref name="version"/> greets a host: the shipped file with that version in its state
    /// (<c>S/@VR</c>). The shipped version leaves the file as it is.
    /// </summary>
    private static string AsDriverVersion(string file, Version version) =>
        version == VirtualKukaControllerOptions.ShippedDriverVersion
            ? file
            : file.Replace($"\"S/@VR\", \"{VirtualKukaControllerOptions.ShippedDriverVersion}\")", $"\"S/@VR\", \"{version.Major}.{version.Minor}\")", StringComparison.Ordinal);
}

using Machina.Simulation.Krl;

namespace Machina.Cli.Commands;

/// <summary><c>machina sim kuka --load FOLDER</c>: the EthernetKRL configurations (.xml) of the folder, as the controller keeps them.</summary>
internal static partial class SimCommand
{
    /// <summary>Gives the twin every EthernetKRL configuration of the program's folder and names each channel in the log.</summary>
    private static async Task AddEkiConfigurationsAsync(KrlTwinController twin, string path, TextWriter output)
    {
        string folder = Directory.Exists(path) ? path : Path.GetDirectoryName(path) ?? ".";
        string[] configurations = Directory.GetFiles(folder, "*.xml");
        Array.Sort(configurations, StringComparer.Ordinal);
        foreach (string file in configurations)
        {
            string text = await File.ReadAllTextAsync(file).ConfigureAwait(false);
            if (!text.Contains("<ETHERNETKRL", StringComparison.OrdinalIgnoreCase))
            {
                continue;
            }
            string name = Path.GetFileNameWithoutExtension(file);
            twin.AddEkiConfiguration(name, text);
            await output.WriteLineAsync($"EthernetKRL channel {name} ({Path.GetFileName(file)}): served when the program opens it (EKI_Open)").ConfigureAwait(false);
        }
    }
}

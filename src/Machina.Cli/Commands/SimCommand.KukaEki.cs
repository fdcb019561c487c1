using Machina.Simulation.Krl;

namespace Machina.Cli.Commands;

/// <summary>
/// <c>machina sim kuka --load FOLDER</c>: the EthernetKRL configurations (.xml) of the folder, and its RSI files (contexts .rsix and
/// .rsi.xml, ETHERNET object configurations .xml), as the controller keeps them.
/// </summary>
internal static partial class SimCommand
{
    /// <summary>Gives the twin every EthernetKRL configuration of the program's folder and names each channel in the log.</summary>
    private static async Task AddEkiConfigurationsAsync(KrlTwinController twin, string path, TextWriter output)
    {
        string folder = Directory.Exists(path) ? path : Path.GetDirectoryName(path) ?? ".";
        string[] configurations = [.. Directory.GetFiles(folder, "*.xml"), .. Directory.GetFiles(folder, "*.rsix")];
        Array.Sort(configurations, StringComparer.Ordinal);
        foreach (string file in configurations)
        {
            string text = await File.ReadAllTextAsync(file).ConfigureAwait(false);
            if (IsRsiFile(file, text))
            {
                twin.AddRsiFile(Path.GetFileName(file), text);
                await output.WriteLineAsync($"RSI file {Path.GetFileName(file)}: read when the program creates its context (RSI_CREATE)").ConfigureAwait(false);
                continue;
            }
            if (!text.Contains("<ETHERNETKRL", StringComparison.OrdinalIgnoreCase))
            {
                continue;
            }
            string name = Path.GetFileNameWithoutExtension(file);
            twin.AddEkiConfiguration(name, text);
            await output.WriteLineAsync($"EthernetKRL channel {name} ({Path.GetFileName(file)}): served when the program opens it (EKI_Open)").ConfigureAwait(false);
        }
    }

    /// <summary>An RSI context (.rsix, .rsi.xml) or an RSI ETHERNET object's configuration (ROOT with CONFIG and IP_NUMBER).</summary>
    private static bool IsRsiFile(string file, string text) =>
        file.EndsWith(".rsix", StringComparison.OrdinalIgnoreCase) || file.EndsWith(".rsi.xml", StringComparison.OrdinalIgnoreCase)
        || (text.Contains("<ROOT>", StringComparison.OrdinalIgnoreCase) && text.Contains("<IP_NUMBER>", StringComparison.OrdinalIgnoreCase));
}

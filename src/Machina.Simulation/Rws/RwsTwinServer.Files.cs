using System.Text;
using static Machina.Simulation.Rws.RwsXhtmlWriter;

namespace Machina.Simulation.Rws;

/// <summary>
/// The file service (<c>/fileservice/$HOME/…</c>) on the controller's mass memory: the same folder that RAPID's <c>HOME:</c> is
/// (<see cref="Rapid.RapidTwinController.HomeDirectory"/>), so a file uploaded here is what <c>Open "HOME:/f"</c> reads, and a file a
/// program wrote is what a client downloads. <c>$TEMP</c> and <c>$RAMDISK</c> are RAPID's <c>TEMP:</c> and <c>RAMDISK:</c>.
/// </summary>
internal sealed partial class RwsTwinServer
{
    /// <summary>The file service's environment variables and the RAPID devices they stand for.</summary>
    private static readonly (string Variable, string Device)[] FileRoots = [("$HOME", "HOME:"), ("$TEMP", "TEMP:"), ("$RAMDISK", "RAMDISK:")];

    /// <summary>The files on the controller's mass memory (RAPID's and the file service's alike), by file-service path (e.g. <c>$HOME/machina_abb_driver.mod</c>).</summary>
    public IReadOnlyDictionary<string, string> Files
    {
        get
        {
            string home = Twin.HomeDirectory;
            var files = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
            foreach (string file in Directory.EnumerateFiles(home, "*", SearchOption.AllDirectories))
            {
                string relative = Path.GetRelativePath(home, file).Replace('\\', '/');
                (string variable, string rest) = FileRoots.Skip(1).FirstOrDefault(r => relative.StartsWith(r.Device[..^1] + "/", StringComparison.OrdinalIgnoreCase)) is { Variable: not null } r
                    ? (r.Variable, relative[r.Device.Length..])
                    : ("$HOME", relative);
                files[variable + "/" + rest] = Encoding.Latin1.GetString(File.ReadAllBytes(file));
            }
            return files;
        }
    }

    /// <summary>
    /// The full path on disk of a file-service path (<c>$HOME/dir/f.mod</c>) or of a RAPID file name (<c>HOME:/f.mod</c>), or null when it
    /// names another folder of the controller.
    /// </summary>
    private string? StorePath(string path)
    {
        if (path.Contains(':', StringComparison.Ordinal))
        {
            return Twin.SandboxPath(path);
        }
        int slash = path.IndexOf('/', StringComparison.Ordinal);
        string root = slash < 0 ? path : path[..slash];
        string? device = FileRoots.FirstOrDefault(r => r.Variable.Equals(root, StringComparison.OrdinalIgnoreCase)).Device;
        return device is null ? null : Twin.SandboxPath(device + "/" + (slash < 0 ? "" : path[(slash + 1)..]));
    }

    private RwsResponse FileService(string path, RwsRequest request, bool get)
    {
        if (FilePathRefusal(path) is { } refusal)
        {
            return Error(400, "Bad Request", null, refusal);
        }
        if (StorePath(path) is not { } full)
        {
            return Error(404, "Not Found", null, $"The twin's file service has $HOME, $TEMP and $RAMDISK (RAPID's HOME:, TEMP: and RAMDISK:), not {PrintableText.Of(path)}.");
        }
        try
        {
            if (get)
            {
                return File.Exists(full)
                    ? new RwsResponse(200, "OK", File.ReadAllBytes(full), "text/plain")
                    : Error(404, "Not Found", null, $"The file {path} does not exist.");
            }
            if (request.Method != "PUT")
            {
                return Error(400, "Bad Request", null, $"The twin's file service takes GET and PUT, not {request.Method}.");
            }
            bool created = !File.Exists(full);
            Directory.CreateDirectory(Path.GetDirectoryName(full)!);
            File.WriteAllBytes(full, request.Body);
            return created ? new RwsResponse(201, "Created", []) : new RwsResponse(200, "OK", []);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            // A folder where a file is asked for, or a file a program holds open for writing.
            return Error(409, "Conflict", null, $"The file {path} cannot be {(get ? "read" : "written")} now: {ex.Message}");
        }
    }

    /// <summary>The text of the module file <paramref name="path"/> on the controller's mass memory, or null when there is none.</summary>
    private string? ReadModuleFile(string path)
    {
        if (FilePathRefusal(path.Replace(":", "", StringComparison.Ordinal).TrimStart('/')) is not null || StorePath(path) is not { } full)
        {
            return null;
        }
        try
        {
            return File.Exists(full) ? Encoding.Latin1.GetString(File.ReadAllBytes(full)) : null;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            return null;
        }
    }

    /// <summary>
    /// Why the file service refuses <paramref name="path"/>, or null: every part of a path names a file or folder under a
    /// controller directory, so <c>..</c>, <c>.</c>, empty parts, backslashes and control characters are refused (a key that
    /// leaves its folder).
    /// </summary>
    private static string? FilePathRefusal(string path)
    {
        string[] parts = path.Split('/');
        if (path.Length == 0 || parts.Any(p => p is "" or "." or "..") || path.Any(c => c == '\\' || char.IsControl(c)))
        {
            return $"The file path {PrintableText.Of(path)} is not a path under a controller folder (no \"..\", \".\", empty parts or backslashes).";
        }
        return null;
    }
}

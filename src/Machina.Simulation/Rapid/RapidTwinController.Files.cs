namespace Machina.Simulation.Rapid;

/// <summary>
/// The controller's mass memory as programs see it (RAPID: Open "HOME:/log.txt"): the devices HOME:, TEMP: and RAMDISK: are folders
/// of one sandbox directory (<see cref="RapidTwinOptions.HomeDirectory"/>, else a new temporary directory); no path leads out of it.
/// </summary>
internal sealed partial class RapidTwinController
{
    private readonly List<RapidFileDevice> _files = [];
    private string? _home;

    /// <summary>The sandbox directory that HOME: stands for (made on first use).</summary>
    public string HomeDirectory
    {
        get
        {
            lock (_files)
            {
                if (_home is null)
                {
                    _home = Options.HomeDirectory is { } home ? Path.GetFullPath(home) : Directory.CreateTempSubdirectory("machina-rapid-home-").FullName;
                    Directory.CreateDirectory(Path.Combine(_home, "TEMP"));
                    Directory.CreateDirectory(Path.Combine(_home, "RAMDISK"));
                }
                return _home;
            }
        }
    }

    /// <summary>Deletes the sandbox when the twin made it (a temporary directory) at the controller's end; a directory the user named is kept.</summary>
    public void RemoveTemporaryHome()
    {
        lock (_files)
        {
            if (_home is null || Options.HomeDirectory is not null)
            {
                return;
            }
            try
            {
                Directory.Delete(_home, recursive: true);
            }
            catch (Exception e) when (e is IOException or UnauthorizedAccessException)
            {
                // A file still open elsewhere: the directory stays in the temporary folder, as any temporary file may.
            }
            _home = null;
        }
    }

    /// <summary>
    /// The full path in the sandbox of a program's file name (<c>HOME:/dir/file.txt</c>, <c>TEMP:x</c>, <c>RAMDISK:/y</c>; the device's
    /// name in any case), or null when it names another device or leads out of the sandbox (<c>HOME:/../x</c>).
    /// </summary>
    public string? SandboxPath(string name)
    {
        int colon = name.IndexOf(':', StringComparison.Ordinal);
        string? folder = colon < 0 ? null : name[..colon].ToUpperInvariant() switch
        {
            "HOME" => "",
            "TEMP" => "TEMP",
            "RAMDISK" => "RAMDISK",
            _ => null,
        };
        if (folder is null)
        {
            return null;
        }
        string root = Path.GetFullPath(Path.Combine(HomeDirectory, folder));
        string rest = name[(colon + 1)..].Replace('\\', '/').TrimStart('/');
        string full = Path.GetFullPath(Path.Combine(root, rest));
        string inside = root.EndsWith(Path.DirectorySeparatorChar) ? root : root + Path.DirectorySeparatorChar;
        return full == root || full.StartsWith(inside, StringComparison.Ordinal) ? full : null;
    }

    /// <summary>Remembers a file a program opened, so that stopping the controller closes it.</summary>
    internal void Track(RapidFileDevice file)
    {
        lock (_files)
        {
            if (!_files.Contains(file))
            {
                _files.Add(file);
            }
        }
    }

    /// <summary>Closes the files programs left open (the controller's stop).</summary>
    private void CloseFiles()
    {
        lock (_files)
        {
            _files.ForEach(f => f.Close());
            _files.Clear();
        }
    }
}

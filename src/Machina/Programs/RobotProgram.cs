using System.Text;

namespace Machina;

/// <summary>A compiled program: one or more files in the device's language, plus the warnings raised while compiling.</summary>
public sealed class RobotProgram
{
    internal RobotProgram(string name, RobotType brand, IReadOnlyList<RobotProgramFile> files, IReadOnlyList<ProgramWarning> warnings)
    {
        Name = name;
        Brand = brand;
        Files = files;
        Warnings = warnings;
    }

    /// <summary>Program name (the robot's name made safe for robot languages).</summary>
    public string Name { get; }

    /// <summary>The language the program is written in.</summary>
    public RobotType Brand { get; }

    /// <summary>The files, in the order they should be loaded.</summary>
    public IReadOnlyList<RobotProgramFile> Files { get; }

    /// <summary>What the device could not do exactly as asked; each also appears as a comment in the code.</summary>
    public IReadOnlyList<ProgramWarning> Warnings { get; }

    /// <summary>
    /// The file that holds the program's instructions, the one to open or run: ABB <c>.mod</c>, KUKA <c>.src</c>, UR <c>.script</c>,
    /// <c>.gcode</c>, … Not always <c>Files[0]</c>: an ABB program lists its <c>.pgf</c> loader first, and a KUKA program may have a
    /// <c>.dat</c> file of targets.
    /// </summary>
    public RobotProgramFile MainFile => Files.FirstOrDefault(f => !IsCompanion(f)) ?? Files[0];

    /// <summary>Files that only accompany the main one: the ABB loader (<c>.pgf</c>) and KUKA data (<c>.dat</c>).</summary>
    private static bool IsCompanion(RobotProgramFile file) =>
        string.Equals(file.Extension, "pgf", StringComparison.OrdinalIgnoreCase) || string.Equals(file.Extension, "dat", StringComparison.OrdinalIgnoreCase);

    /// <summary>The file with this extension (e.g. "mod"), or null.</summary>
    public RobotProgramFile? GetFile(string extension) =>
        Files.FirstOrDefault(f => string.Equals(f.Extension, extension, StringComparison.OrdinalIgnoreCase));

    /// <summary>Every file's lines one after the other, each file framed by start and end comment lines.</summary>
    public IReadOnlyList<string> ToStringList()
    {
        var lines = new List<string>();
        foreach (RobotProgramFile file in Files)
        {
            string bar = string.Concat(Enumerable.Repeat(file.CommentPrefix, Math.Max(1, 65 / Math.Max(1, file.CommentPrefix.Length))));
            lines.Add(bar);
            lines.Add($"{file.CommentPrefix} FILE \"{file.FileName}\"");
            lines.Add(bar);
            lines.AddRange(file.Lines);
            lines.Add("");
        }
        return lines;
    }

    /// <summary>
    /// Writes every file into <paramref name="folderPath"/> (created if missing; existing files with the same names are replaced,
    /// nothing else is touched). Lines end with <paramref name="newLine"/> (default "\n"). Returns the paths written.
    /// </summary>
    /// <exception cref="IOException">The disk refused (the folder is a file, the disk is full, …).</exception>
    /// <exception cref="UnauthorizedAccessException">No permission to write there.</exception>
    public IReadOnlyList<string> SaveToFolder(string folderPath, string newLine = "\n")
    {
        if (string.IsNullOrWhiteSpace(folderPath))
        {
            throw new ArgumentException("Give a folder to save the program to.", nameof(folderPath));
        }
        Directory.CreateDirectory(folderPath);
        var written = new List<string>();
        foreach (RobotProgramFile file in Files)
        {
            string path = Path.Combine(folderPath, file.FileName);
            using (var stream = new FileStream(path, FileMode.Create, FileAccess.Write, FileShare.None))
            using (var writer = new StreamWriter(stream, file.Encoding))
            {
                file.WriteTo(writer, newLine);
            }
            written.Add(path);
        }
        return written;
    }

    /// <summary>Text such as <c>Robot Program "HelloRobot" with 2 files.</c>.</summary>
    public override string ToString() => $"Robot Program \"{Name}\" with {Counted.Of(Files.Count, "file")}.";

    /// <summary>Encoding for robot controller files: 7-bit ASCII; other characters become '?'.</summary>
    internal static Encoding Ascii => Encoding.ASCII;

    /// <summary>Encoding for listings: UTF-8 with a byte order mark.</summary>
    internal static Encoding Utf8Bom { get; } = new UTF8Encoding(encoderShouldEmitUTF8Identifier: true);
}

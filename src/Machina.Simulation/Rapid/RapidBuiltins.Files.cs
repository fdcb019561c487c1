using System.Globalization;
using System.Text;

namespace Machina.Simulation.Rapid;

/// <summary>
/// File and serial channel instructions on files of the controller's mass memory (RAPID reference: Open, Close, Write, ReadStr,
/// ReadNum, Rewind, IsFile, RemoveFile, MakeDir), kept in the twin's sandbox (<see cref="RapidTwinController.HomeDirectory"/>): a name
/// of another device or leading out of it raises ERR_FILEOPEN. Without \Read, \Append or \Bin, Open writes a new file (\Write).
/// Write ends its line with a line feed unless \NoNewLine; ReadStr reads a line (at most 80 characters, to a line feed or a \Delim
/// character) and returns EOF at the end of the file, ReadNum returns EOF_NUM there.
/// </summary>
internal static partial class RapidBuiltins
{
    private const int MaxReadCharacters = 80;

    private static IEnumerable<RapidBuiltin> Files() =>
    [
        Instruction("Open", [P("Object", "string"), Opt("File", "string"), P("IODevice", "iodev"), Sw("Read"), Sw("Write"), Sw("Append"), Sw("Bin")], call =>
        {
            var device = (RapidFileDevice)call.Value(2);
            string name = call.Str(0) + (call.Has(1) ? "/" + call.Str(1) : "");
            if (device.Stream is not null)
            {
                throw call.Error(RapidErrorNumbers.ByName["ERR_FILEOPEN"], $"Open: the I/O device is already open (\"{name}\")");
            }
            RapidTwinController c = call.Machine.Task.Controller;
            string path = c.SandboxPath(name)
                ?? throw call.Error(RapidErrorNumbers.ByName["ERR_FILEOPEN"], $"Open: \"{name}\" is not a file of the twin's HOME:, TEMP: or RAMDISK:");
            (FileMode mode, FileAccess access) = call.Has(3) ? (FileMode.Open, FileAccess.Read)
                : call.Has(5) ? (FileMode.Append, FileAccess.Write)
                : call.Has(6) ? (FileMode.OpenOrCreate, FileAccess.ReadWrite)
                : (FileMode.Create, FileAccess.Write);
            try
            {
                device.Open(path, mode, access);
            }
            catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
            {
                throw call.Error(RapidErrorNumbers.ByName["ERR_FILEOPEN"], $"Open: the file \"{name}\" cannot be opened ({ex.GetType().Name})");
            }
            c.Track(device);
        }),
        Instruction("Close", [P("IODevice", "iodev")], call => ((RapidFileDevice)call.Value(0)).Close()),
        Instruction("Rewind", [P("IODevice", "iodev")], call => ((RapidFileDevice)call.Value(0)).Rewind()),
        Instruction("Write", [P("IODevice", "iodev"), P("String", "string"), Opt("Num", "num"), Opt("Bool", "bool"), Opt("Pos", "pos"), Opt("Orient", "orient"),
            Opt("Dnum", "dnum"), Sw("NoNewLine")], call =>
        {
            StreamWriter writer = ((RapidFileDevice)call.Value(0)).Writer ?? throw FileAccessError(call, "Write", "writing");
            string text = call.Str(1) + string.Concat(Enumerable.Range(2, 5).Where(call.Has).Select(p => RapidValues.ToText(call.Value(p))));
            Access(call, () => writer.Write(call.Has(7) ? text : text + "\n"));
        }),
        Function("ReadStr", "string", [P("IODevice", "iodev"), Sw("Line"), Sw("Bin"), Opt("Delim", "string"), Sw("RemoveCR"), Sw("DiscardHeaders"), Opt("Time", "num")], call =>
        {
            StreamReader reader = ((RapidFileDevice)call.Value(0)).Reader ?? throw FileAccessError(call, "ReadStr", "reading");
            if (ReadField(call, reader, call.Has(3) ? call.Str(3) : "") is not { } text)
            {
                return "EOF";
            }
            return call.Has(4) && text.EndsWith('\r') ? text[..^1] : text;
        }),
        Function("ReadNum", "num", [P("IODevice", "iodev"), Opt("Delim", "string"), Opt("Time", "num")], call =>
        {
            StreamReader reader = ((RapidFileDevice)call.Value(0)).Reader ?? throw FileAccessError(call, "ReadNum", "reading");
            if (ReadField(call, reader, call.Has(1) ? call.Str(1) : "") is not { } text)
            {
                return 9.998E36; // EOF_NUM
            }
            return double.TryParse(text.Trim(), NumberStyles.Float, CultureInfo.InvariantCulture, out double value)
                ? value
                : throw call.Error(RapidErrorNumbers.ByName["ERR_RCVDATA"], $"ReadNum: \"{text.Trim()}\" is not a number");
        }),
        Function("IsFile", "bool", [P("Object", "string"), Sw("Directory"), Sw("Fifo"), Sw("RegFile"), Sw("BlockSpec"), Sw("CharSpec")], call =>
        {
            string? path = call.Machine.Task.Controller.SandboxPath(call.Str(0));
            return path is not null && (call.Has(1) ? Directory.Exists(path)
                : call.Has(3) ? File.Exists(path)
                : !(call.Has(2) || call.Has(4) || call.Has(5)) && (File.Exists(path) || Directory.Exists(path)));
        }),
        Instruction("RemoveFile", [P("Path", "string")], call =>
        {
            string path = FilePath(call, "RemoveFile");
            if (!File.Exists(path))
            {
                throw call.Error(RapidErrorNumbers.ByName["ERR_FILEACC"], $"RemoveFile: there is no file \"{call.Str(0)}\"");
            }
            Access(call, () => File.Delete(path));
        }),
        Instruction("MakeDir", [P("Path", "string")], call =>
        {
            string path = FilePath(call, "MakeDir");
            if (File.Exists(path) || Directory.Exists(path))
            {
                throw call.Error(RapidErrorNumbers.ByName["ERR_FILEEXIST"], $"MakeDir: \"{call.Str(0)}\" already exists");
            }
            Access(call, () => Directory.CreateDirectory(path));
        }),
    ];

    /// <summary>Reads up to a line feed or a character of <paramref name="delimiters"/> (not kept), at most 80 characters; null at the end of the file.</summary>
    private static string? ReadField(RapidCall call, StreamReader reader, string delimiters)
    {
        string? text = null;
        Access(call, () =>
        {
            if (reader.Peek() < 0)
            {
                return;
            }
            var field = new StringBuilder();
            while (field.Length < MaxReadCharacters && reader.Read() is int c and >= 0)
            {
                if (c == '\n' || delimiters.Contains((char)c, StringComparison.Ordinal))
                {
                    break;
                }
                field.Append((char)c);
            }
            text = field.ToString();
        });
        return text;
    }

    private static string FilePath(RapidCall call, string name) => call.Machine.Task.Controller.SandboxPath(call.Str(0))
        ?? throw call.Error(RapidErrorNumbers.ByName["ERR_FILEACC"], $"{name}: \"{call.Str(0)}\" is not in the twin's HOME:, TEMP: or RAMDISK:");

    private static RapidRuntimeException FileAccessError(RapidCall call, string name, string purpose) =>
        call.Error(RapidErrorNumbers.ByName["ERR_FILEACC"], $"{name}: the I/O device is not open for {purpose}");

    /// <summary>Runs a file operation; a failure of the file system is the program's ERR_FILEACC.</summary>
    private static void Access(RapidCall call, Action operation)
    {
        try
        {
            operation();
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            throw call.Error(RapidErrorNumbers.ByName["ERR_FILEACC"], $"the file could not be accessed ({ex.GetType().Name})");
        }
    }
}

using System.Text;

namespace Machina;

/// <summary>One file of a compiled program, e.g. <c>HelloRobot.mod</c>: its name, extension, text encoding and lines.</summary>
public sealed class RobotProgramFile
{
    internal RobotProgramFile(string name, string extension, Encoding encoding, string commentPrefix, IReadOnlyList<string> lines)
    {
        Name = name;
        Extension = extension;
        Encoding = encoding;
        CommentPrefix = commentPrefix;
        Lines = lines;
    }

    /// <summary>File name without extension.</summary>
    public string Name { get; }

    /// <summary>Extension without the dot, e.g. "mod".</summary>
    public string Extension { get; }

    /// <summary>File name with extension.</summary>
    public string FileName => Name + "." + Extension;

    /// <summary>Text encoding used when saving: ASCII for robot controllers, UTF-8 with BOM for listings.</summary>
    public Encoding Encoding { get; }

    /// <summary>What starts a comment line in this file's language, e.g. "!" for RAPID.</summary>
    public string CommentPrefix { get; }

    /// <summary>The lines of code, without line endings.</summary>
    public IReadOnlyList<string> Lines { get; }

    /// <summary>The whole file as text, each line ended by <paramref name="newLine"/> (default "\n").</summary>
    /// <exception cref="InvalidOperationException">The file is too long for one string (over about 10^9 characters); save it with <c>SaveToFolder</c> instead.</exception>
    public string ToText(string newLine = "\n")
    {
        ArgumentNullException.ThrowIfNull(newLine);
        if (Lines is PackedLines packed)
        {
            // The text is written once, straight into the string (a StringBuilder would hold it and then copy it).
            long length = packed.CharacterCount + (long)packed.Count * newLine.Length;
            if (length > Array.MaxLength)
            {
                throw new InvalidOperationException($"\"{FileName}\" has {length:N0} characters, too many for one string; save it with SaveToFolder instead.");
            }
            if (length == 0)
            {
                return "";
            }
            // A new string, filled before anyone else sees it (as string.Create fills one), through memory that another thread
            // can take: a long text is copied in two halves at once (PackedLines.CopyTo).
            string text = new('\0', (int)length);
            packed.CopyTo(System.Runtime.InteropServices.MemoryMarshal.AsMemory(text.AsMemory()), newLine);
            return text;
        }
        var sb = new StringBuilder();
        foreach (string line in Lines)
        {
            sb.Append(line).Append(newLine);
        }
        return sb.ToString();
    }

    /// <summary>Writes the lines, each ended by <paramref name="newLine"/>.</summary>
    internal void WriteTo(TextWriter writer, string newLine)
    {
        if (Lines is PackedLines packed)
        {
            packed.WriteTo(writer, newLine);
            return;
        }
        foreach (string line in Lines)
        {
            writer.Write(line);
            writer.Write(newLine);
        }
    }

    /// <summary>Text such as <c>Robot Program File "HelloRobot.mod" with 40 lines of code.</c>.</summary>
    public override string ToString() => $"Robot Program File \"{FileName}\" with {Counted.Of(Lines.Count, "line")} of code.";
}

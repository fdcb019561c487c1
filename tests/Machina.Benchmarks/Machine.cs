using System.Diagnostics;
using System.Runtime.InteropServices;

namespace Machina.Benchmarks;

/// <summary>What the numbers were measured on: CPU, cores, runtime, OS, commit.</summary>
internal sealed record Machine(string Cpu, int Cores, string Runtime, string Os, string Commit, bool ServerGc, string Configuration)
{
    /// <summary>The load average over the last minute (other programs competing for the cores), or null when unknown.</summary>
    public static string LoadAverage()
    {
        try
        {
            return File.ReadAllText("/proc/loadavg").Split(' ')[0];
        }
        catch (IOException)
        {
            return "unknown";
        }
    }

    /// <summary>
    /// Minor page faults of this process so far (Linux, field 10 of /proc/self/stat), or 0 when unknown. Read with one system call
    /// into a buffer on the stack and parsed as bytes: <c>File.ReadAllText</c> and <c>Split</c> brought the file stream, reader and
    /// decoder into a fresh child that otherwise never reads a file, inside the work the <c>cold-issue-text</c> row times.
    /// </summary>
    public static long MinorPageFaults()
    {
        Span<byte> buffer = stackalloc byte[4096];
        int length;
        try
        {
            using Microsoft.Win32.SafeHandles.SafeFileHandle handle = File.OpenHandle("/proc/self/stat");
            length = RandomAccess.Read(handle, buffer, 0);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return 0;
        }
        ReadOnlySpan<byte> stat = buffer[..length];
        int at = stat.LastIndexOf((byte)')') + 2; // after the command name, which is in parentheses and may contain spaces
        for (int field = 0; field < 7 && at > 1; field++)
        {
            int space = stat[at..].IndexOf((byte)' ');
            at = space < 0 ? 0 : at + space + 1;
        }
        long value = 0;
        for (; at > 1 && at < stat.Length && stat[at] is >= (byte)'0' and <= (byte)'9'; at++)
        {
            value = (value * 10) + (stat[at] - '0');
        }
        return value;
    }

    /// <summary>
    /// The fields of a /proc stat file after the command name (which is in parentheses and may contain spaces): field 10 of
    /// the file (minflt) is [7], utime and stime are [11] and [12]; null when the file cannot be read (the process is gone).
    /// </summary>
    public static string[]? StatFields(string path)
    {
        try
        {
            string stat = File.ReadAllText(path);
            return stat[(stat.LastIndexOf(')') + 2)..].Split(' ');
        }
        catch (IOException)
        {
            return null;
        }
    }

    /// <summary>A memory line of a /proc status file (<c>VmRSS:</c>, <c>VmHWM:</c>) in bytes; 0 when the file or the line is missing.</summary>
    public static long StatusBytes(string path, string key)
    {
        try
        {
            string? line = File.ReadLines(path).FirstOrDefault(l => l.StartsWith(key, StringComparison.Ordinal));
            return line is null ? 0 : long.Parse(line[key.Length..].Trim().Split(' ')[0], System.Globalization.CultureInfo.InvariantCulture) * 1024;
        }
        catch (IOException)
        {
            return 0;
        }
    }

    public static Machine Current() => new(
        CpuModel(),
        Environment.ProcessorCount,
        RuntimeInformation.FrameworkDescription,
        RuntimeInformation.OSDescription,
        GitCommit(),
        System.Runtime.GCSettings.IsServerGC,
#if DEBUG
        "Debug");
#else
        "Release");
#endif

    public override string ToString() =>
        $"CPU: {Cpu}, {Cores} cores | {Runtime} | {Os} | {(ServerGc ? "server" : "workstation")} GC | {Configuration} | commit {Commit}";

    private static string CpuModel()
    {
        try
        {
            string? line = File.ReadLines("/proc/cpuinfo").FirstOrDefault(l => l.StartsWith("model name", StringComparison.Ordinal));
            return line is null ? RuntimeInformation.ProcessArchitecture.ToString() : line[(line.IndexOf(':') + 1)..].Trim();
        }
        catch (IOException)
        {
            return RuntimeInformation.ProcessArchitecture.ToString();
        }
    }

    private static string GitCommit()
    {
        try
        {
            using var git = Process.Start(new ProcessStartInfo("git", "rev-parse --short HEAD")
            {
                RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false,
            });
            if (git is null)
            {
                return "unknown";
            }
            string output = git.StandardOutput.ReadToEnd().Trim();
            git.WaitForExit(5000);
            return git.ExitCode == 0 && output.Length > 0 ? output : "unknown";
        }
        catch (Exception ex) when (ex is System.ComponentModel.Win32Exception or InvalidOperationException)
        {
            return "unknown";
        }
    }
}

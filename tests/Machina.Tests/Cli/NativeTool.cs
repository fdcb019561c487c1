using System.Diagnostics;
using System.Runtime.InteropServices;
using System.Text;
using Machina.Tests.Conventions;

namespace Machina.Tests.Cli;

/// <summary>
/// The native linux-x64 <c>machina</c> (PublishAot): <c>MACHINA_NATIVE</c> when set (.ci/run sets it after publishing; the
/// tests then fail if it is missing), otherwise where <c>dotnet publish src/Machina.Cli -p:PublishProfile=linux-x64</c> puts it.
/// </summary>
internal static class NativeTool
{
    /// <summary>Where the published tool lands, from the repository root.</summary>
    internal const string DefaultPath = "src/Machina.Cli/bin/native/linux-x64/machina";

    /// <summary>The path set by <c>MACHINA_NATIVE</c>, or null.</summary>
    internal static string? Required => Environment.GetEnvironmentVariable("MACHINA_NATIVE") is { Length: > 0 } path ? Path.GetFullPath(path) : null;

    /// <summary>The tool's path (it may not exist).</summary>
    internal static string Executable => Required ?? Path.Combine(ConventionTests.RepositoryRoot(), DefaultPath);

    /// <summary>Why the native tests cannot run here, or null when they can.</summary>
    internal static string? Missing()
    {
        if (Required is not null)
        {
            return null;
        }
        if (!OperatingSystem.IsLinux() || RuntimeInformation.OSArchitecture != Architecture.X64)
        {
            return "The native machina is built here for linux-x64 only.";
        }
        return File.Exists(Executable) ? null
            : $"The native machina is not built ({DefaultPath}); build it with: dotnet publish src/Machina.Cli -p:PublishProfile=linux-x64 "
              + "(needs clang and zlib1g-dev), or run .ci/run, which builds it and sets MACHINA_NATIVE so that these tests always run.";
    }

    /// <summary>Starts the tool with <paramref name="args"/> in <paramref name="folder"/>, output and errors captured.</summary>
    internal static NativeProcess Start(string folder, params string[] args) => StartProgram(Executable, folder, args);

    /// <summary>Starts <paramref name="program"/> with <paramref name="args"/> in <paramref name="folder"/>, output and errors captured.</summary>
    internal static NativeProcess StartProgram(string program, string folder, IEnumerable<string> args)
    {
        var info = new ProcessStartInfo(program)
        {
            WorkingDirectory = folder,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            RedirectStandardInput = true,
            UseShellExecute = false,
            StandardOutputEncoding = Encoding.UTF8,
            StandardErrorEncoding = Encoding.UTF8,
        };
        foreach (string arg in args)
        {
            info.ArgumentList.Add(arg);
        }
        return new NativeProcess(Process.Start(info) ?? throw new InvalidOperationException($"Could not start {program}."));
    }

    /// <summary>Runs the tool to its end (at most two minutes) and returns its exit code and output.</summary>
    internal static async Task<CliResult> RunAsync(string folder, params string[] args)
    {
        using NativeProcess process = Start(folder, args);
        process.Process.StandardInput.Close();
        return await process.WaitAsync(TimeSpan.FromMinutes(2));
    }

    /// <summary>Asks a process to stop as Ctrl+C would (SIGTERM, which the tool handles the same way), with the system's kill.</summary>
    internal static void Terminate(Process process)
    {
        using Process kill = Process.Start(new ProcessStartInfo("kill", ["-TERM", process.Id.ToString(System.Globalization.CultureInfo.InvariantCulture)]) { UseShellExecute = false })
            ?? throw new InvalidOperationException("Could not start kill.");
        Assert.True(kill.WaitForExit(30_000), "kill -TERM did not finish in 30 s");
        Assert.Equal(0, kill.ExitCode);
    }
}

/// <summary>A running native tool whose output is read as it comes; disposing kills it if it is still running.</summary>
internal sealed class NativeProcess : IDisposable
{
    private readonly StringBuilder _stdout = new();
    private readonly StringBuilder _stderr = new();
    private readonly Lock _gate = new();
    private readonly Task _readOut;
    private readonly Task _readErr;
    private readonly TaskCompletionSource<string> _firstLine = new(TaskCreationOptions.RunContinuationsAsynchronously);

    internal NativeProcess(Process process)
    {
        Process = process;
        _readOut = Task.Run(async () =>
        {
            while (await process.StandardOutput.ReadLineAsync() is string line)
            {
                lock (_gate)
                {
                    _stdout.Append(line).Append('\n');
                }
                _firstLine.TrySetResult(line);
            }
            _firstLine.TrySetException(new InvalidOperationException("The tool ended without printing a line."));
        });
        _readErr = Task.Run(async () =>
        {
            while (await process.StandardError.ReadLineAsync() is string line)
            {
                lock (_gate)
                {
                    _stderr.Append(line).Append('\n');
                }
            }
        });
    }

    /// <summary>The process.</summary>
    internal Process Process { get; }

    /// <summary>The first line of standard output (bounded by <paramref name="limit"/>).</summary>
    internal Task<string> FirstLineAsync(TimeSpan limit) => _firstLine.Task.WaitAsync(limit);

    /// <summary>Waits (at most <paramref name="limit"/>) for the process to end and returns what it printed.</summary>
    internal async Task<CliResult> WaitAsync(TimeSpan limit)
    {
        using var timeout = new CancellationTokenSource(limit);
        await Process.WaitForExitAsync(timeout.Token);
        await Task.WhenAll(_readOut, _readErr).WaitAsync(limit);
        lock (_gate)
        {
            return new CliResult(Process.ExitCode, _stdout.ToString(), _stderr.ToString());
        }
    }

    public void Dispose()
    {
        try
        {
            if (!Process.HasExited)
            {
                Process.Kill();
                Process.WaitForExit(10_000);
            }
        }
        catch (InvalidOperationException)
        {
        }
        Process.Dispose();
    }
}

/// <summary>A fact that runs the native tool: skipped, with the reason, when it is not built here.</summary>
public sealed class NativeFactAttribute : FactAttribute
{
    /// <summary>Sets <see cref="FactAttribute.Skip"/> when the native tool is missing.</summary>
    public NativeFactAttribute() => Skip = NativeTool.Missing();
}

/// <summary>A theory that runs the native tool: skipped, with the reason, when it is not built here.</summary>
public sealed class NativeTheoryAttribute : TheoryAttribute
{
    /// <summary>Sets <see cref="FactAttribute.Skip"/> when the native tool is missing.</summary>
    public NativeTheoryAttribute() => Skip = NativeTool.Missing();
}

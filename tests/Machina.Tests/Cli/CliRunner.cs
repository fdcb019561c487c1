using System.Text;
using Machina.Cli;

namespace Machina.Tests.Cli;

/// <summary>Runs the machina command in-process in a temporary working folder and keeps what it printed.</summary>
internal sealed class CliRunner : IDisposable
{
    internal CliRunner() => Folder = Directory.CreateTempSubdirectory("machina-cli-").FullName;

    /// <summary>The working folder of the commands (deleted at the end).</summary>
    internal string Folder { get; }

    /// <summary>Writes a file into the working folder and returns its name.</summary>
    internal string Write(string name, string text)
    {
        File.WriteAllText(Path.Combine(Folder, name), text);
        return name;
    }

    /// <summary>Writes <paramref name="program"/> to p.machina and runs <c>machina COMMAND p.machina OPTIONS</c> to its end.</summary>
    internal async Task<CliResult> RunProgramAsync(string command, string program, params string[] options) =>
        await RunAsync([command, Write("p.machina", program), .. options]);

    /// <summary>Runs a command line to its end.</summary>
    internal async Task<CliResult> RunAsync(params string[] args) => await RunAsync(args, "", CancellationToken.None);

    /// <summary>Runs a command line with standard input <paramref name="stdin"/>, cancelled by <paramref name="cancellation"/> (Ctrl+C).</summary>
    internal async Task<CliResult> RunAsync(string[] args, string stdin, CancellationToken cancellation,
        WatchedWriter? stdout = null, Action<string>? ready = null, bool isTerminal = false, TimeProvider? time = null)
    {
        stdout ??= new WatchedWriter();
        var stderr = new WatchedWriter();
        var context = new CliContext(new StringReader(stdin), stdout, stderr, cancellation, isTerminal, time, Folder) { Ready = ready };
        int exit = await CliApp.RunAsync(args, context).WaitAsync(TimeSpan.FromMinutes(2));
        return new CliResult(exit, stdout.Text, stderr.Text);
    }

    /// <summary>Runs a command line whose standard input is <paramref name="stdin"/> (e.g. keys a test types while it runs).</summary>
    internal async Task<CliResult> RunAsync(string[] args, TextReader stdin, WatchedWriter stdout)
    {
        var stderr = new WatchedWriter();
        var context = new CliContext(stdin, stdout, stderr, CancellationToken.None, false, null, Folder);
        int exit = await CliApp.RunAsync(args, context).WaitAsync(TimeSpan.FromMinutes(2));
        return new CliResult(exit, stdout.Text, stderr.Text);
    }

    /// <summary>The full path of a file in the working folder.</summary>
    internal string PathOf(string name) => Path.Combine(Folder, name);

    public void Dispose()
    {
        try
        {
            Directory.Delete(Folder, recursive: true);
        }
        catch (IOException)
        {
        }
    }
}

/// <summary>What a command returned and printed.</summary>
internal sealed record CliResult(int Exit, string Stdout, string Stderr)
{
    /// <summary>The non-empty lines of standard output.</summary>
    internal string[] Lines => Stdout.Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
}

/// <summary>A thread-safe text writer whose text a test can wait on.</summary>
internal sealed class WatchedWriter : TextWriter
{
    private readonly StringBuilder _text = new();
    private readonly Lock _gate = new();
    private readonly List<(string Text, TaskCompletionSource Seen)> _waits = [];

    public override Encoding Encoding => Encoding.UTF8;

    internal string Text
    {
        get
        {
            lock (_gate)
            {
                return _text.ToString();
            }
        }
    }

    public override void Write(char value) => Write(value.ToString());

    public override void Write(string? value)
    {
        if (value is null)
        {
            return;
        }
        lock (_gate)
        {
            _text.Append(value);
            string all = _text.ToString();
            foreach (var wait in _waits.Where(w => all.Contains(w.Text, StringComparison.Ordinal)).ToList())
            {
                wait.Seen.TrySetResult();
                _waits.Remove(wait);
            }
        }
    }

    public override void WriteLine(string? value) => Write(value + "\n");

    public override Task WriteLineAsync(string? value)
    {
        WriteLine(value);
        return Task.CompletedTask;
    }

    public override Task WriteAsync(string? value)
    {
        Write(value);
        return Task.CompletedTask;
    }

    /// <summary>Completes when the text contains <paramref name="text"/> (at most 60 s).</summary>
    internal Task WaitForAsync(string text)
    {
        var seen = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        lock (_gate)
        {
            if (_text.ToString().Contains(text, StringComparison.Ordinal))
            {
                return Task.CompletedTask;
            }
            _waits.Add((text, seen));
        }
        return seen.Task.WaitAsync(TimeSpan.FromSeconds(60));
    }
}

#if NET10_0_OR_GREATER
// The command-line tool is built for .NET 10 only (see Machina.Tests.csproj).
using Machina.Tests.Cli;

namespace Machina.Tests.Docs;

/// <summary>
/// Every <c>machina</c> command in a shell block of README.md and docs/cli.md runs as written from a fresh clone (issue 46):
/// each line <c>dotnet run --project src/Machina.Cli -- …</c> or <c>machina …</c> (also after <c>cat FILE |</c>) runs the built
/// tool (Machina.Cli.dll, as its own process) in a temporary folder laid out as the clone (samples/programs/, and the page's own
/// square.machina for docs/cli.md, whose examples use it), at most two minutes each. The commands that need a real robot or that
/// run until Ctrl+C are listed in <see cref="NotRun"/> with the reason; the rest must end with the exit code the page gives them.
/// </summary>
public class DocCommandsTests
{
    /// <summary>Commands not run, with why (each must still be on its page: a stale entry fails).</summary>
    private static readonly Dictionary<string, string> NotRun = new(StringComparer.Ordinal)
    {
        ["sim abb --port 7000"] = "runs until Ctrl+C, on a fixed port of a shared machine",
        ["sim abb"] = "runs until Ctrl+C, on the fixed port 7000 of a shared machine",
        ["sim abb --bind 0.0.0.0"] = "runs until Ctrl+C and listens beyond loopback",
        ["run square.machina --brand abb --host 192.168.125.1 --port 7000"] = "needs a real ABB controller running Machina's driver",
    };

    /// <summary>Commands that run until Ctrl+C and are started, seen running, then stopped as Ctrl+C stops them (SIGTERM).</summary>
    private static readonly HashSet<string> UntilStopped = new(StringComparer.Ordinal)
    {
        "sim abb --port 0 --speed-factor 10 --model \"IRB 120\"",
    };

    /// <summary>Commands that end with exit code 1 by design (the page says so).</summary>
    private static readonly Dictionary<string, int> ExitCodes = new(StringComparer.Ordinal)
    {
        ["check samples/programs/too-far.machina --model \"IRB 120\""] = 1,   // "The exit code is 1 when anything was found"
    };

    public static TheoryData<string, string> Commands()
    {
        var data = new TheoryData<string, string>();
        foreach (string page in (string[])["README.md", "docs/cli.md"])
        {
            foreach (string command in CommandsOf(page))
            {
                data.Add(page, command);
            }
        }
        return data;
    }

    [Fact]
    public void Pages_HaveTheCommandsThisTestKnows()
    {
        List<string> all = [.. Commands().Select(row => Strip((string)row[1]))];
        Assert.True(all.Count >= 20, $"only {all.Count} commands found: {string.Join(" | ", all)}");
        Assert.All(NotRun.Keys.Concat(UntilStopped).Concat(ExitCodes.Keys),
            known => Assert.True(all.Contains(known), $"\"{known}\" is no longer on README.md or docs/cli.md: remove it from this test."));
    }

    [Theory]
    [MemberData(nameof(Commands))]
    public async Task Command_RunsAsWritten(string page, string command)
    {
        string args = Strip(command);
        if (NotRun.TryGetValue(args, out string? why))
        {
            Assert.False(string.IsNullOrWhiteSpace(why));
            return;
        }
        using var clone = new CliRunner();
        Layout(clone.Folder, page);
        (string[] words, string? stdinFile) = Parse(command);
        if (UntilStopped.Contains(args))
        {
            using NativeProcess running = Start(clone.Folder, words, null);
            string first = await running.FirstLineAsync(TimeSpan.FromMinutes(1));
            Assert.Contains("listening", first, StringComparison.Ordinal);
            NativeTool.Terminate(running.Process);
            CliResult stopped = await running.WaitAsync(TimeSpan.FromMinutes(1));
            Assert.True(stopped.Exit == 0, $"{page}: \"{command}\" exited with {stopped.Exit} when stopped:\n{stopped.Stdout}\n{stopped.Stderr}");
            return;
        }
        using NativeProcess process = Start(clone.Folder, words, stdinFile is null ? null : File.ReadAllText(Path.Combine(clone.Folder, stdinFile)));
        CliResult result = await process.WaitAsync(TimeSpan.FromMinutes(2));
        int expected = ExitCodes.GetValueOrDefault(args, 0);
        Assert.True(result.Exit == expected,
            $"{page}: \"{command}\" exited with {result.Exit}, not {expected}:\n{result.Stdout}\n{result.Stderr}");
    }

    /// <summary>The command lines of a page's shell blocks, as written (comments after # removed).</summary>
    private static IEnumerable<string> CommandsOf(string page)
    {
        string? language = null;
        foreach (string line in DocText.ReadLines(page))
        {
            if (line.StartsWith("```", StringComparison.Ordinal))
            {
                language = language is null ? line[3..].Trim() : null;
                continue;
            }
            if (language is not ("sh" or "bash" or "shell"))
            {
                continue;
            }
            string text = WithoutComment(line).Trim();
            if (text.StartsWith(Project, StringComparison.Ordinal) || text.StartsWith("machina ", StringComparison.Ordinal) || text.Contains("| machina ", StringComparison.Ordinal))
            {
                yield return text;
            }
        }
    }

    private const string Project = "dotnet run --project src/Machina.Cli -- ";

    /// <summary>The arguments of a command: what follows <c>machina</c> or <c>dotnet run … --</c>.</summary>
    private static string Strip(string command)
    {
        int pipe = command.IndexOf("| machina ", StringComparison.Ordinal);
        string text = pipe >= 0 ? command[(pipe + 2)..] : command;
        return text.StartsWith(Project, StringComparison.Ordinal) ? text[Project.Length..] : text["machina ".Length..];
    }

    /// <summary>The arguments as the shell splits them, and the file piped in by <c>cat FILE |</c> (or null).</summary>
    private static (string[] Words, string? Stdin) Parse(string command)
    {
        string? stdin = null;
        int pipe = command.IndexOf("| machina ", StringComparison.Ordinal);
        if (pipe >= 0)
        {
            string[] cat = GettingStartedCommandTests.Split(command[..pipe]);
            Assert.True(cat is ["cat", _], $"only \"cat FILE | machina …\" pipes are understood, not \"{command}\"");
            stdin = cat[1];
        }
        return (GettingStartedCommandTests.Split(Strip(command)), stdin);
    }

    /// <summary>The folder as a fresh clone has it (samples/programs/), plus docs/cli.md's own square.machina for that page's commands.</summary>
    private static void Layout(string folder, string page)
    {
        string programs = Path.Combine(folder, "samples", "programs");
        Directory.CreateDirectory(programs);
        foreach (string file in Directory.EnumerateFiles(DocText.PathOf("samples/programs")))
        {
            File.Copy(file, Path.Combine(programs, Path.GetFileName(file)));
        }
        if (page == "docs/cli.md")
        {
            List<string> lines = DocText.ReadLines(page);
            int open = lines.FindIndex(l => l == "// square.machina") - 1;
            Assert.True(open >= 0 && lines[open] == "```text", "docs/cli.md has no ```text block starting with // square.machina");
            int close = lines.FindIndex(open + 1, l => l == "```");
            File.WriteAllText(Path.Combine(folder, "square.machina"), string.Join('\n', lines[(open + 1)..close]) + "\n");
        }
    }

    /// <summary>Starts the built tool (Machina.Cli.dll next to the tests) with <paramref name="args"/> in <paramref name="folder"/>.</summary>
    private static NativeProcess Start(string folder, string[] args, string? stdin)
    {
        string host = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH") is { Length: > 0 } path ? path : "dotnet";
        NativeProcess process = NativeTool.StartProgram(host, folder, [Path.Combine(AppContext.BaseDirectory, "Machina.Cli.dll"), .. args]);
        if (stdin is not null)
        {
            process.Process.StandardInput.Write(stdin);
        }
        process.Process.StandardInput.Close();
        return process;
    }

    /// <summary>A shell line without its trailing <c># comment</c> (a # after a space, outside quotes).</summary>
    private static string WithoutComment(string line)
    {
        bool quoted = false;
        for (int i = 0; i < line.Length; i++)
        {
            if (line[i] == '"')
            {
                quoted = !quoted;
            }
            else if (line[i] == '#' && !quoted && (i == 0 || line[i - 1] == ' '))
            {
                return line[..i];
            }
        }
        return line;
    }
}
#endif

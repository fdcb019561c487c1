#if NET10_0_OR_GREATER
// The command-line tool is built for .NET 10 only (see Machina.Tests.csproj).
using System.Text;
using Machina.Tests.Cli;

namespace Machina.Tests.Docs;

/// <summary>The `machina` commands of docs/getting-started.md run, in-process, on the page's own program file, and do what the page says.</summary>
public class GettingStartedCommandTests
{
    [Fact]
    public async Task GettingStarted_Commands_RunOnThePagesProgram()
    {
        Dictionary<string, string> fences = DocText.CheckedFences(DocText.ReadLines(GettingStartedDocTests.Page));
        using var cli = new CliRunner();
        cli.Write("square.machina", fences["square"] + "\n");
        string[] commands = fences["commands"].Split('\n', StringSplitOptions.RemoveEmptyEntries);
        Assert.Equal(4, commands.Length);
        var results = new List<CliResult>();

        foreach (string command in commands)
        {
            string[] args = Split(command);
            Assert.Equal("machina", args[0]);
            CliResult result = await cli.RunAsync(args[1..]);
            Assert.True(result.Exit == 0, $"\"{command}\" exited with {result.Exit}:\n{result.Stdout}\n{result.Stderr}");
            results.Add(result);
        }

        // compile: the RAPID files, with the square's corners.
        Assert.Equal(2, results[0].Lines.Length);
        string module = File.ReadAllText(cli.PathOf(Path.Combine("build", "square.mod")));
        Assert.Contains("MoveL [[400, 50, 400], [0, 0, 1, 0]", module, StringComparison.Ordinal);
        Assert.True(File.Exists(cli.PathOf(Path.Combine("build", "square.pgf"))));
        // check: six motions, all fine for an IRB 120.
        Assert.Contains("6 motions checked: 6 ok, 0 with problems, 0 refused (of 7 actions).", results[1].Stdout, StringComparison.Ordinal);
        // preview: an SVG drawing.
        Assert.StartsWith("<svg", File.ReadAllText(cli.PathOf("square.svg")).TrimStart(), StringComparison.Ordinal);
        // run --sim: all seven actions executed by the virtual controller.
        Assert.Contains("Done: 7 actions executed. The robot is at ", results[3].Stdout, StringComparison.Ordinal);
    }

    /// <summary>Splits a shell command line at spaces, keeping "double-quoted" words together.</summary>
    internal static string[] Split(string line)
    {
        var words = new List<string>();
        var word = new StringBuilder();
        bool quoted = false;
        foreach (char c in line)
        {
            if (c == '"')
            {
                quoted = !quoted;
            }
            else if (c == ' ' && !quoted)
            {
                if (word.Length > 0)
                {
                    words.Add(word.ToString());
                    word.Clear();
                }
            }
            else
            {
                word.Append(c);
            }
        }
        if (word.Length > 0)
        {
            words.Add(word.ToString());
        }
        return [.. words];
    }
}
#endif

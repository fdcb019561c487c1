using System.Reflection;

namespace Machina.Tests.Docs;

/// <summary>
/// Every C# snippet of docs/getting-started.md is code that compiles here (<see cref="GettingStartedExamples"/>), and the
/// ones that need no real robot run and print what the page says they print.
/// </summary>
public class GettingStartedDocTests
{
    internal const string Page = "docs/getting-started.md";

    [Fact]
    public void GettingStarted_EveryCSharpSnippet_IsTheCompiledExample()
    {
        Dictionary<string, string> fences = DocText.CheckedFences(DocText.ReadLines(Page));
        Dictionary<string, string> bodies = DocText.MethodBodies("tests/Machina.Tests/Docs/GettingStartedExamples.cs");
        string source = File.ReadAllText(DocText.PathOf("tests/Machina.Tests/Docs/GettingStartedExamples.cs"));
        var csharp = typeof(GettingStartedExamples).GetMethods(BindingFlags.NonPublic | BindingFlags.Static).Select(m => m.Name).ToArray();

        Assert.Equal(["FirstOfflineProgram", "FirstRealRobot", "FirstVirtualRobot"], csharp.Order(StringComparer.Ordinal));
        foreach (string name in csharp)
        {
            Assert.True(fences.TryGetValue(name, out string? fence), $"{Page} has no \"<!-- checked: {name} -->\" snippet.");
            string[] lines = fence!.Split('\n');
            string[] usings = [.. lines.TakeWhile(l => l.StartsWith("using ", StringComparison.Ordinal))];
            Assert.NotEmpty(usings);
            Assert.All(usings, u => Assert.Contains("\n" + u + "\n", "\n" + source, StringComparison.Ordinal));
            string code = string.Join("\n", lines.Skip(usings.Length).SkipWhile(l => l.Length == 0));
            Assert.Equal(bodies[name], code);
        }
    }

    [Fact]
    public void FirstOfflineProgram_PrintsAndSavesTheRapidModule()
    {
        string folder = Path.GetFullPath(Path.Combine("programs", "FirstProgram_Program"));
        using var output = new StringWriter();

        GettingStartedExamples.FirstOfflineProgram(output);

        string module = File.ReadAllText(Path.Combine(folder, "FirstProgram.mod"));
        Assert.True(File.Exists(Path.Combine(folder, "FirstProgram.pgf")));
        Assert.Contains("    MoveL [[300, 100, 400], [0, 0, 1, 0], [0,0,0,0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel50, z5, Tool0\\WObj:=WObj0;", module, StringComparison.Ordinal);
        Assert.Contains("    WaitTime 1;", module, StringComparison.Ordinal);
        Assert.Contains("    MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9,9E9,9E9,9E9,9E9,9E9]], vel50, z5, Tool0\\WObj:=WObj0;", module, StringComparison.Ordinal);
        Assert.Equal(module.Replace("\r\n", "\n", StringComparison.Ordinal).TrimEnd(), output.ToString().Replace("\r\n", "\n", StringComparison.Ordinal).TrimEnd());
        string[] shown = DocText.CheckedFences(DocText.ReadLines(Page))["FirstOfflineProgramOutput"].Split('\n');
        Assert.Equal(2, shown.Length);
        Assert.All(shown, line => Assert.Contains("\n" + line + "\n", output.ToString(), StringComparison.Ordinal));
        Directory.Delete(folder, recursive: true);
    }

    [Fact]
    public async Task FirstVirtualRobot_EventsComeInOrderAndTheRobotEndsWhereTheProgramSays()
    {
        using var text = new StringWriter();
        using var output = TextWriter.Synchronized(text);

        await GettingStartedExamples.FirstVirtualRobot(output).WaitAsync(TimeSpan.FromMinutes(2));

        string[] lines = text.ToString().Split('\n', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        Assert.StartsWith("Connected: the tool is at [", lines[0], StringComparison.Ordinal);
        Assert.Equal("Done: the joints are at [0, 0, 0, 0, 90, 0]", lines[^1]);
        // Five actions (ids 1 to 5), each issued, then released, then executed.
        for (int id = 1; id <= 5; id++)
        {
            int issued = Array.FindIndex(lines, l => l.StartsWith($"issued   #{id} ", StringComparison.Ordinal));
            int released = Array.IndexOf(lines, $"released #{id}");
            int executed = Array.FindIndex(lines, l => l.StartsWith($"executed #{id}:", StringComparison.Ordinal));
            Assert.True(issued > 0 && issued < released && released < executed, $"action {id}: issued at {issued}, released at {released}, executed at {executed}");
        }
        Assert.Contains("executed #2: the tool is at [300, 100, 400]", lines);
        Assert.Contains("executed #3: the tool is at [300, 100, 300]", lines);
    }
}

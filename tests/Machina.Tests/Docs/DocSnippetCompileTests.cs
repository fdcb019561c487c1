#if NET10_0_OR_GREATER
using System.Diagnostics;
using System.Text;
using System.Text.RegularExpressions;
using Machina.Tests.Conventions;

namespace Machina.Tests.Docs;

/// <summary>
/// Compiles every C# block of the README, PACKAGE.md and docs/ together, with the C# compiler the .NET SDK ships (csc.dll, run
/// once; no package is added), against .NET's and ASP.NET Core's reference assemblies (for Microsoft.Extensions.Logging) and
/// Machina's libraries. Each block becomes the body of a method of its own; its <c>using</c> lines go to the top of its file.
/// A block with no <c>using</c> line is a fragment and gets <c>using Machina;</c>. A fragment's free variables are declared by
/// a comment on the line before the block, <c>&lt;!-- snippet-context: Robot bot, ILogger myLogger --&gt;</c> (they become
/// the method's parameters); docs/reference.md's examples take <c>Robot bot</c> (they are the bodies of ReferenceExamples)
/// unless they declare it.
/// Signature listings (after <c>&lt;!-- generated: signatures --&gt;</c> or <c>&lt;!-- snippet: signatures --&gt;</c>) are
/// not code and are left out. Errors are reported at the markdown file and line.
/// </summary>
public sealed partial class DocSnippetCompileTests
{
    /// <summary>The markdown files whose C# blocks are compiled, relative to the repository root.</summary>
    private static IEnumerable<string> Pages()
    {
        string root = ConventionTests.RepositoryRoot();
        yield return "README.md";
        yield return "PACKAGE.md";
        foreach (string page in Directory.EnumerateFiles(Path.Combine(root, "docs"), "*.md").Order(StringComparer.Ordinal))
        {
            yield return Path.GetRelativePath(root, page).Replace('\\', '/');
        }
    }

    /// <summary>One C# block: where it is, its lines (with their line numbers in the page) and the parameters its body takes.</summary>
    private sealed record Snippet(string Page, int FirstLine, List<(int Line, string Text)> Lines, string Context);

    [Fact]
    public async Task EveryCSharpBlock_OfTheReadmeAndTheDocs_Compiles()
    {
        List<Snippet> snippets = [.. Pages().SelectMany(Read)];
        Assert.True(snippets.Count >= 20, $"Only {snippets.Count} C# blocks found; the reader of the pages is broken.");
        Assert.Contains(snippets, s => s.Page == "README.md" && s.Lines.Any(l => l.Text.Contains("AddSink", StringComparison.Ordinal)));

        string folder = Directory.CreateTempSubdirectory("machina-snippets-").FullName;
        try
        {
            var sources = new List<string> { Write(folder, "Globals.cs", GlobalUsings) };
            for (int i = 0; i < snippets.Count; i++)
            {
                sources.Add(Write(folder, $"Snippet{i}.cs", Source(snippets[i], i)));
            }
            (int exit, string output) = await CompileAsync(folder, sources);
            string[] errors = [.. output.Split('\n').Select(l => l.TrimEnd('\r')).Where(l => ErrorLine().IsMatch(l))];
            Assert.True(errors.Length == 0 && exit == 0,
                $"{errors.Length} compile errors in the C# blocks of the docs (csc exit {exit}):\n" + (errors.Length > 0 ? string.Join("\n", errors) : output));
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void Reader_FindsFragmentsWithTheirContext_AndLeavesOutSignatures()
    {
        List<Snippet> readme = [.. Read("README.md")];
        Snippet logging = Assert.Single(readme, s => s.Lines.Any(l => l.Text.Contains("AddSink", StringComparison.Ordinal)));
        Assert.Equal("Robot bot, ILogger myLogger", logging.Context);
        Assert.Equal("using Microsoft.Extensions.Logging;", logging.Lines[1].Text);
        Assert.DoesNotContain(Read("docs/reference.md"), s => s.Lines.Any(l => l.Text.StartsWith("static Robot Create(", StringComparison.Ordinal)));
        List<Snippet> reference = [.. Read("docs/reference.md")];
        Assert.Equal("", Assert.Single(reference, s => s.Lines.Any(l => l.Text == "var bot = Robot.Create(\"Drawing\", \"UR\", \"UR5e\");")).Context);
        Assert.True(reference.Count(s => s.Context == "Robot bot") >= 40, "docs/reference.md's examples are bodies of methods taking Robot bot.");
    }

    private const string GlobalUsings = """
        global using System;
        global using System.Collections.Generic;
        global using System.IO;
        global using System.Linq;
        global using System.Net.Http;
        global using System.Threading;
        global using System.Threading.Tasks;
        """;

    /// <summary>The C# blocks of a page, with the context comment before each.</summary>
    private static IEnumerable<Snippet> Read(string page)
    {
        List<string> lines = DocText.ReadLines(page);
        for (int i = 0; i < lines.Count; i++)
        {
            if (lines[i].Trim() is not ("```csharp" or "```cs" or "```c#"))
            {
                continue;
            }
            string before = i > 0 ? lines[i - 1].Trim() : "";
            int end = lines.FindIndex(i + 1, l => l.TrimStart().StartsWith("```", StringComparison.Ordinal));
            Assert.True(end > i, $"{page}:{i + 1}: a C# block that never ends.");
            bool signatures = before is "<!-- generated: signatures -->" or "<!-- snippet: signatures -->";
            if (!signatures)
            {
                Match context = ContextComment().Match(before);
                List<(int Line, string Text)> block = [.. Enumerable.Range(i + 1, end - i - 1).Select(k => (k + 1, lines[k]))];
                bool declaresBot = block.Any(l => DeclaresBot().IsMatch(l.Text));
                string parameters = context.Success ? context.Groups["context"].Value.Trim() : page == "docs/reference.md" && !declaresBot ? "Robot bot" : "";
                yield return new Snippet(page, i + 2, block, parameters);
            }
            i = end;
        }
    }

    /// <summary>The file for one block: its using lines first, then its body in a method of its own, with #line back to the page.</summary>
    private static string Source(Snippet snippet, int index)
    {
        var sb = new StringBuilder();
        string page = snippet.Page;
        bool anyUsing = false;
        var body = new List<(int Line, string Text)>();
        foreach ((int line, string text) in snippet.Lines)
        {
            if (UsingLine().IsMatch(text))
            {
                anyUsing = true;
                sb.Append("#line ").Append(line).Append(" \"").Append(page).Append("\"\n").Append(text).Append('\n');
            }
            else
            {
                body.Add((line, text));
            }
        }
        if (!anyUsing)
        {
            sb.Append("using Machina;\n");
        }
        sb.Append("#line default\n");
        sb.Append("namespace DocSnippets.S").Append(index).Append("\n{\n    internal static class Block\n    {\n");
        sb.Append("        internal static async Task Run(").Append(snippet.Context).Append(")\n        {\n");
        foreach ((int line, string text) in body)
        {
            sb.Append("#line ").Append(line).Append(" \"").Append(page).Append("\"\n").Append(text).Append('\n');
        }
        sb.Append("#line default\n            await Task.CompletedTask;\n        }\n    }\n}\n");
        return sb.ToString();
    }

    private static string Write(string folder, string name, string text)
    {
        string path = Path.Combine(folder, name);
        File.WriteAllText(path, text);
        return path;
    }

    /// <summary>Runs the SDK's csc.dll once on every file; returns its exit code and output.</summary>
    private static async Task<(int Exit, string Output)> CompileAsync(string folder, List<string> sources)
    {
        string dotnetRoot = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(typeof(object).Assembly.Location)!, "..", "..", ".."));
        string dotnet = Path.Combine(dotnetRoot, OperatingSystem.IsWindows() ? "dotnet.exe" : "dotnet");
        string csc = Newest(Path.Combine(dotnetRoot, "sdk"), v => Path.Combine(v, "Roslyn", "bincore", "csc.dll"));
        string netRef = Newest(Path.Combine(dotnetRoot, "packs", "Microsoft.NETCore.App.Ref"), v => Path.Combine(v, "ref", "net10.0"));
        string aspRef = Newest(Path.Combine(dotnetRoot, "packs", "Microsoft.AspNetCore.App.Ref"), v => Path.Combine(v, "ref", "net10.0"));
        Assert.True(File.Exists(dotnet), $"No dotnet at {dotnet}.");

        var rsp = new StringBuilder("-nologo\n-noconfig\n-nostdlib+\n-target:library\n-langversion:latest\n-nullable:enable\n");
        rsp.Append("-out:\"").Append(Path.Combine(folder, "Snippets.dll")).Append("\"\n");
        IEnumerable<string> references = Directory.EnumerateFiles(netRef, "*.dll")
            .Concat(Directory.EnumerateFiles(aspRef, "*.dll"))
            .Concat([typeof(Robot).Assembly.Location, typeof(Machina.Simulation.VirtualAbbController).Assembly.Location,
                typeof(Machina.Bridge.BridgeServer).Assembly.Location]);
        foreach (string reference in references)
        {
            rsp.Append("-r:\"").Append(reference).Append("\"\n");
        }
        foreach (string source in sources)
        {
            rsp.Append('"').Append(source).Append("\"\n");
        }
        string rspPath = Write(folder, "csc.rsp", rsp.ToString());

        var start = new ProcessStartInfo(dotnet) { RedirectStandardOutput = true, RedirectStandardError = true, UseShellExecute = false, WorkingDirectory = folder };
        start.ArgumentList.Add(csc);
        start.ArgumentList.Add("@" + rspPath);
        using var process = Process.Start(start) ?? throw new InvalidOperationException("csc did not start.");
        Task<string> stdout = process.StandardOutput.ReadToEndAsync();
        Task<string> stderr = process.StandardError.ReadToEndAsync();
        using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(3));
        try
        {
            await process.WaitForExitAsync(timeout.Token);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            throw new TimeoutException("csc took more than 3 minutes to compile the docs' C# blocks.");
        }
        return (process.ExitCode, await stdout + await stderr);
    }

    /// <summary>The path <paramref name="pick"/> gives for the newest version folder under <paramref name="parent"/> where it exists.</summary>
    private static string Newest(string parent, Func<string, string> pick)
    {
        string? found = Directory.Exists(parent)
            ? Directory.EnumerateDirectories(parent)
                .Select(d => (Version: Version.TryParse(Path.GetFileName(d).Split('-')[0], out Version? v) ? v : new Version(0, 0), Path: pick(d)))
                .Where(x => File.Exists(x.Path) || Directory.Exists(x.Path))
                .OrderByDescending(x => x.Version)
                .Select(x => x.Path)
                .FirstOrDefault()
            : null;
        return found ?? throw new InvalidOperationException($"Nothing usable under {parent}: the docs' C# blocks are compiled with the .NET SDK's own compiler.");
    }

    [GeneratedRegex(@"^\s*(var|Robot)\s+bot\s*=")]
    private static partial Regex DeclaresBot();

    [GeneratedRegex(@"^<!-- snippet-context: (?<context>.*) -->$")]
    private static partial Regex ContextComment();

    [GeneratedRegex(@"^\s*using\s+(static\s+)?[\w.]+(\s*=\s*[\w.<>]+)?\s*;")]
    private static partial Regex UsingLine();

    [GeneratedRegex(@"\): error CS\d+: ")]
    private static partial Regex ErrorLine();
}
#endif

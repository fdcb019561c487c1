using Machina.Tests.Conventions;

namespace Machina.Tests.Docs;

/// <summary>
/// Words a newcomer met that were no longer true: online control for ABB only, a stub bridge, UR and KUKA "to come", a
/// design file that is not in the repository, three samples of seven. Each test names the page and the stale words.
/// </summary>
public sealed class StaleWordsDocTests
{
    [Theory]
    [InlineData("docs/bridge.md", "for ABB today")]
    [InlineData("docs/bridge.md", "the virtual controller exists for ABB")]
    [InlineData("docs/cli.md", "is a stub")]
    [InlineData("docs/cli.md", "once their virtual controllers exist")]
    [InlineData("PACKAGE.md", "a virtual ABB controller")]
    [InlineData("src/Machina/Robot.Connection.cs", "Online control is available for ABB robots.")]
    [InlineData("docs/adding-a-device.md", "it went in last")]
    [InlineData("docs/architecture.md", "All machine-readable text uses `Num`")]
    [InlineData("docs/architecture.md", "every switch over action kinds names the kinds it handles")]
    public void Page_DoesNotSayStaleWords(string page, string stale)
    {
        string text = File.ReadAllText(DocText.PathOf(page)).Replace("\r\n", "\n").Replace("\n", " ");
        Assert.DoesNotContain(stale, text, StringComparison.Ordinal);
    }

    [Fact]
    public void Architecture_CitesOnlyFilesOfTheRepository_AndListsEverySample()
    {
        string root = ConventionTests.RepositoryRoot();
        string text = File.ReadAllText(DocText.PathOf("docs/architecture.md"));
        if (!File.Exists(Path.Combine(root, "DESIGN.md")))
        {
            Assert.DoesNotContain("`DESIGN.md`", text, StringComparison.Ordinal);
        }
        string[] samples = [.. Directory.EnumerateDirectories(Path.Combine(root, "samples"))
            .Where(d => File.Exists(Path.Combine(d, Path.GetFileName(d) + ".csproj")))
            .Select(d => Path.GetFileName(d)!)];
        Assert.Equal(7, samples.Length);
        string layout = text[text.IndexOf("samples/ ", StringComparison.Ordinal)..];
        layout = layout[..layout.IndexOf("```", StringComparison.Ordinal)];
        Assert.All(samples, s => Assert.Contains(s, layout, StringComparison.Ordinal));
    }
}

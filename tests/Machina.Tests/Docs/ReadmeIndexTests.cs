namespace Machina.Tests.Docs;

/// <summary>The README's "Documentation" index links every page of docs/, so that a new page cannot be left unfindable.</summary>
public class ReadmeIndexTests
{
    [Fact]
    public void ReadmeDocumentationIndex_LinksEveryDocsPage()
    {
        string readme = File.ReadAllText(DocText.PathOf("README.md"));
        int start = readme.IndexOf("\n## Documentation\n", StringComparison.Ordinal);
        Assert.True(start >= 0, "README.md has no \"## Documentation\" section.");
        int end = readme.IndexOf("\n## ", start + 1, StringComparison.Ordinal);
        string index = readme[start..(end < 0 ? readme.Length : end)];

        string[] pages = [.. Directory.EnumerateFiles(DocText.PathOf("docs"), "*.md").Select(Path.GetFileName).Order(StringComparer.Ordinal)!];
        string[] unlinked = [.. pages.Where(p => !index.Contains($"](docs/{p})", StringComparison.Ordinal))];

        Assert.Contains("reference.md", pages);
        Assert.True(unlinked.Length == 0, $"README.md's Documentation section does not link: {string.Join(", ", unlinked)}");
    }
}

using System.Xml.Linq;

namespace Machina.Tests.Docs;

/// <summary>
/// docs/concepts.svg, the diagram of docs/concepts.md, is a drawing a person can see: a well-formed SVG of the size the page
/// expects, and (with Chromium) a rendering that is not blank and shows the three stages in their colours. The rendering
/// is saved as docs/concepts.png.
/// </summary>
public class ConceptsDiagramTests
{
    internal const int Width = 1200;
    internal const int Height = 820;

    [Fact]
    public void ConceptsSvg_IsWellFormedWithItsSizeAndIsShownByThePage()
    {
        XElement svg = XDocument.Load(DocText.PathOf("docs/concepts.svg")).Root!;

        Assert.Equal("svg", svg.Name.LocalName);
        Assert.Equal(Width.ToString(System.Globalization.CultureInfo.InvariantCulture), svg.Attribute("width")?.Value);
        Assert.Equal(Height.ToString(System.Globalization.CultureInfo.InvariantCulture), svg.Attribute("height")?.Value);
        string[] texts = [.. svg.Descendants().Where(e => e.Name.LocalName == "text").Select(e => e.Value)];
        foreach (string label in new[] { "Issue cursor", "Release cursor", "Execution cursor", "Motion cursor", "ActionIssued", "ActionReleased", "ActionExecuted" })
        {
            Assert.Contains(label, texts);
        }
        Assert.Contains("](concepts.svg)", File.ReadAllText(DocText.PathOf("docs/concepts.md")), StringComparison.Ordinal);
    }

#if NET10_0_OR_GREATER
    // Chromium is driven by the Bridge tests' helper, built for .NET 10 only.
    [Bridge.ChromiumFact]
    public async Task ConceptsSvg_RenderedInChromium_IsNotBlankAndShowsTheStages()
    {
        await using Bridge.Chromium browser = await Bridge.Chromium.StartAsync(Width, Height);
        await browser.NavigateAsync(new Uri(DocText.PathOf("docs/concepts.svg")));
        await browser.WaitForAsync("document.readyState", "complete");
        // One animation frame so that the screenshot holds the drawn picture.
        await browser.EvaluateAsync("new Promise(r => requestAnimationFrame(() => r(0)))");

        byte[] png = await browser.ScreenshotAsync();
        await File.WriteAllBytesAsync(DocText.PathOf("docs/concepts.png"), png);
        PngImage image = PngImage.Decode(png);

        Assert.Equal((Width, Height), (image.Width, image.Height));
        int inked = 0;
        var colours = new HashSet<int>();
        for (int y = 0; y < image.Height; y++)
        {
            for (int x = 0; x < image.Width; x++)
            {
                int rgb = image.Rgb(x, y);
                colours.Add(rgb);
                inked += rgb == 0xFFFFFF ? 0 : 1;
            }
        }
        double share = inked / (double)(image.Width * image.Height);
        Assert.True(share is > 0.05 and < 0.6, $"{share:P1} of the pixels are not white: the picture is blank or a solid block.");
        Assert.True(colours.Count > 50, $"only {colours.Count} colours: no text or shapes were drawn");
        // Inside the boxes of action 1 (executed, green), 5 (released, orange) and 10 (issued, blue).
        AssertColour(image, 74, 226, 0xD7EEDB);
        AssertColour(image, 378, 226, 0xFFE6C7);
        AssertColour(image, 758, 226, 0xDCE8F8);
    }

    private static void AssertColour(PngImage image, int x, int y, int expected)
    {
        int actual = image.Rgb(x, y);
        int Channel(int rgb, int shift) => (rgb >> shift) & 0xFF;
        bool close = new[] { 16, 8, 0 }.All(s => Math.Abs(Channel(actual, s) - Channel(expected, s)) <= 4);
        Assert.True(close, $"pixel ({x}, {y}) is #{actual:X6}, expected about #{expected:X6}");
    }
#endif
}

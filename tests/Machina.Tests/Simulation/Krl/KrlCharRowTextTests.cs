using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// <see cref="KrlValues.SetText"/>: EKI_GetString's and a STRING assignment's write of text into a CHAR array or a row of one
/// (<c>text[i, ]</c>): the text's characters, every other element of the row unset (also characters a longer text or a direct
/// element write left past the end), the text cut at the row's end, and nothing outside the row touched.
/// </summary>
public class KrlCharRowTextTests
{
    [Fact]
    public void ShorterText_UnsetsTheRestOfTheRow_AndLeavesTheOtherRowsAlone()
    {
        object[] items = Rows(3, 8, 'z');
        KrlValues.SetText(items, 8, 8, "abcdef");
        items[8 + 7] = 'q'; // a direct element write after the text's end
        KrlValues.SetText(items, 8, 8, "xy");

        Assert.Equal("zzzzzzzz|xy\0\0\0\0\0\0|zzzzzzzz", Show(items, 8));
    }

    [Fact]
    public void EmptyText_UnsetsTheWholeRow()
    {
        object[] items = Rows(2, 5, 'k');
        KrlValues.SetText(items, 0, 5, "");

        Assert.Equal("\0\0\0\0\0|kkkkk", Show(items, 5));
    }

    [Fact]
    public void LongerText_IsCutAtTheRowsEnd()
    {
        object[] items = Rows(2, 4, '\0');
        KrlValues.SetText(items, 4, 4, "abcdefgh");

        Assert.Equal("\0\0\0\0|abcd", Show(items, 4));
    }

    [Fact]
    public void Characters_AreTheSharedBoxesBelow256_AndTheirOwnAbove()
    {
        object[] items = new object[4]; // a new array: no element holds a box yet
        KrlValues.SetText(items, 0, 4, "a\u00e9\u20ac");

        Assert.Equal(['a', '\u00e9', '\u20ac', '\0'], items.Cast<char>());
        Assert.Same(KrlValues.Box('a'), items[0]);
        Assert.Same(KrlValues.Box('\0'), items[3]);
    }

    [Fact]
    public void AnUnsharedBoxOfTheSameCharacter_IsReplacedByTheSharedOne()
    {
        object[] items = [(object)'\0', (object)'a'];
        KrlValues.SetText(items, 0, 2, "");

        Assert.Same(KrlValues.Box('\0'), items[0]);
        Assert.Same(KrlValues.Box('\0'), items[1]);
    }

    /// <summary><paramref name="rows"/> rows of <paramref name="length"/> elements, each holding <paramref name="fill"/>'s shared box.</summary>
    private static object[] Rows(int rows, int length, char fill) => [.. Enumerable.Repeat(KrlValues.Box(fill), rows * length)];

    /// <summary>The elements' characters, a | between rows of <paramref name="length"/>.</summary>
    private static string Show(object[] items, int length) =>
        string.Join("|", items.Chunk(length).Select(row => new string([.. row.Cast<char>()])));
}

using System.Text;

namespace Machina.Tests.Utilities;

public class AsciiNarrowTests
{
    [Fact]
    public void TryWrite_AsciiOfEveryLength_TheBytesOfTheEncoder()
    {
        var random = new Random(48);
        for (int length = 0; length <= 70; length++)
        {
            string text = new(Enumerable.Range(0, length).Select(_ => (char)random.Next(0, 128)).ToArray());
            var bytes = new byte[length + 4];

            int written = AsciiNarrow.TryWrite(text, bytes);

            Assert.Equal(length, written);
            Assert.Equal(Encoding.ASCII.GetBytes(text), bytes[..length]);
        }
    }

    [Theory]
    [InlineData('é')]
    [InlineData('\u0080')]
    [InlineData('\uD83E')]
    [InlineData('日')]
    public void TryWrite_OneCharacterOutsideAsciiAnywhere_Refused(char other)
    {
        for (int length = 1; length <= 40; length++)
        {
            for (int at = 0; at < length; at++)
            {
                char[] text = Enumerable.Repeat('a', length).ToArray();
                text[at] = other;

                Assert.Equal(-1, AsciiNarrow.TryWrite(text, new byte[length]));
            }
        }
    }

    [Fact]
    public void TryWrite_DestinationTooShort_Throws()
    {
        Assert.Throws<ArgumentOutOfRangeException>(() => AsciiNarrow.TryWrite("Move [1, 2, 3] mm", new byte[4]));
    }
}

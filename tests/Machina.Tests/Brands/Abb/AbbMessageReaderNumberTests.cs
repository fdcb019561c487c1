using System.Globalization;
using System.Text;

namespace Machina.Tests.Brands.Abb;

/// <summary>
/// The ABB reader's whole numbers (ids and codes): short runs of digits are read without the culture's number format, and
/// every token reads exactly as <c>int.TryParse</c> with the invariant culture reads it, accepted or refused alike.
/// </summary>
public sealed class AbbMessageReaderNumberTests
{
    [Theory]
    [InlineData("0")]
    [InlineData("7")]
    [InlineData("0042")]
    [InlineData("123456789")]
    [InlineData("999999999")]
    [InlineData("1234567890")]
    [InlineData("2147483647")]
    [InlineData("2147483648")]
    [InlineData("99999999999")]
    [InlineData("-5")]
    [InlineData("+5")]
    [InlineData("-2147483648")]
    [InlineData("-")]
    [InlineData("+")]
    [InlineData("1a")]
    [InlineData("a1")]
    [InlineData("1.0")]
    [InlineData("1e3")]
    [InlineData("12/")]
    [InlineData("12:")]
    [InlineData("1\0")]
    [InlineData("0x10")]
    public void TryParseInt_ReadsAsIntTryParse(string text)
    {
        byte[] token = Encoding.ASCII.GetBytes(text);
        bool expected = int.TryParse(token, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int expectedValue);

        bool read = AbbMessageReader.TryParseInt(token, out int value);

        Assert.Equal(expected, read);
        Assert.Equal(expectedValue, value);
    }

    [Fact]
    public void AnAcknowledgement_ReadsItsIdAndCode()
    {
        var reader = new AbbMessageReader();
        reader.Append("@123456789 1;@0042 30;"u8);

        Assert.True(reader.TryRead(out AbbMessage first));
        Assert.True(reader.TryRead(out AbbMessage second));

        Assert.Equal((AbbMessageKind.Acknowledgement, 123456789, 1), (first.Kind, first.Id, first.Code));
        Assert.Equal((AbbMessageKind.Acknowledgement, 42, 30), (second.Kind, second.Id, second.Code));
    }
}

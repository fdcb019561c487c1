using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// StrToVal's reading of plain number text without the runtime's general parser (issue 45), and StrFind/StrMatch positions: the
/// values are those the general parser gives, bit for bit (the sign of zero included), and every other text still goes to it.
/// </summary>
public class RapidNumberTextTests
{
    [Theory]
    [InlineData("751")]
    [InlineData("0")]
    [InlineData("-0")]
    [InlineData("-0.0")]
    [InlineData("1121.5")]
    [InlineData("0.1")]
    [InlineData("-12.345")]
    [InlineData("0001.2500")]
    [InlineData("999999999999999")]
    [InlineData("0.00000000000001")]
    [InlineData("123456.789012345")]
    public void PlainText_IsTheGeneralParsersDouble(string text)
    {
        Assert.True(RapidNumberText.TryParsePlain(text, out double value));
        double expected = double.Parse(text, System.Globalization.CultureInfo.InvariantCulture);
        Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(value));
    }

    [Theory]
    [InlineData("")]
    [InlineData("-")]
    [InlineData("1.")]
    [InlineData(".5")]
    [InlineData("+1")]
    [InlineData("1e5")]
    [InlineData("1.2.3")]
    [InlineData(" 1")]
    [InlineData("1234567890123456")]
    [InlineData("0.000000000000001")]
    [InlineData("0.1234567890123456")]
    [InlineData("--1")]
    [InlineData("1-")]
    public void OtherText_GoesToTheGeneralParser(string text)
    {
        Assert.False(RapidNumberText.TryParsePlain(text, out double value));
        Assert.Equal(0, value);
    }

    [Fact]
    public void RandomPlainText_AgreesWithTheGeneralParser_BitForBit()
    {
        var random = new Random(45);
        int read = 0;
        for (int n = 0; n < 20_000; n++)
        {
            int length = random.Next(1, 18);
            var text = new System.Text.StringBuilder(random.Next(4) == 0 ? "-" : "");
            int point = random.Next(3) == 0 ? -1 : random.Next(1, length + 1);
            for (int i = 0; i < length; i++)
            {
                if (i == point)
                {
                    text.Append('.');
                }
                text.Append((char)('0' + random.Next(10)));
            }
            string s = text.ToString();
            bool plain = RapidNumberText.TryParsePlain(s, out double value);
            Assert.True(double.TryParse(s, System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture, out double expected), s);
            if (plain)
            {
                read++;
                Assert.True(BitConverter.DoubleToInt64Bits(expected) == BitConverter.DoubleToInt64Bits(value), $"{s}: {value:R} instead of {expected:R}");
            }
            else
            {
                Assert.True(s.Count(char.IsDigit) > 15, s); // only text with too many digits is left to the general parser
            }
        }
        Assert.True(read > 10_000, $"{read}"); // most of the text was read by the plain path
    }

    [Fact]
    public void StrToValAndStrFind_InAProgram_GiveTheManualsValues()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", """
            MODULE T
            PROC main()
              VAR num value;
              VAR bool ok;
              ok := StrToVal("1121.5", value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal(" -0.25 ", value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal("1234567890123456", value);
              TPWrite ValToStr(ok) + " " + NumToStr(value, 0);
              ok := StrToVal("2.5E2", value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal("1.", value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              ok := StrToVal("1-", value);
              TPWrite ValToStr(ok) + " " + ValToStr(value);
              TPWrite ValToStr(StrFind("@12 1 751;", 2, "0123456789 " \NotInSet) + StrFind("abc", 1, "") * 100 + StrFind("abc", 2, "" \NotInSet) * 10000);
              TPWrite ValToStr(StrFind("abc", 4, "a")) + " " + ValToStr(StrMatch("a  b", 1, "  ")) + " " + ValToStr(StrFind("a;b c", 1, " ;"));
            ENDPROC
            ENDMODULE
            """));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["TRUE 1121.5", "TRUE -0.25", "TRUE 1234567890123456", "TRUE 250", "TRUE 1", "FALSE 1", "20410", "4 2 2"], twin.Pendant.Lines);
    }
}

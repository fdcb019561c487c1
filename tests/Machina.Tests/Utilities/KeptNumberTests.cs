namespace Machina.Tests.Utilities;

public class KeptNumberTests
{
    [Fact]
    public void WriteAscii_TheGeneralTextOfEachNumber_KeptOrWrittenAnew()
    {
        // Short numbers (bytes straight from the shortest digits), long and tiny ones (G15's general text narrowed), repeats
        // (the kept text) and values that differ only in their bits (−0 and 0).
        double[] values = [5, 5, 7.44, 7.44, 3.719, 0, -0.0, 0.1 + 0.2, 1.0 / 3, 1e-5, 1e-5, 2.5e-7, 1e14, 1e20, -12345.678901, 0.0001, 99999999999999.9, 5];
        var kept = new KeptNumber();
        byte[] line = new byte[8 + NumAppend.MaxChars];
        foreach (double value in values)
        {
            int end = kept.WriteAscii(line, 3, value);
            Assert.Equal(Num.G(value), System.Text.Encoding.ASCII.GetString(line, 3, end - 3));
        }
    }
}

using System.Globalization;
using System.Text;

namespace Machina.Tests.Brands.Abb;

public class AbbRequestTests
{
    [Fact]
    public void Move_Linear_MatchesOriginalWireText() =>
        Assert.Equal("@12 1 400 0 500 0 0 1 0;", AbbRequest.Move(12, true, new Vector(400, 0, 500), Rotation.FromQuaternion(0, 0, 1, 0)).ToWireText());

    [Fact]
    public void Move_Joint_RoundsMillimetresTo3AndQuaternionTo4Decimals()
    {
        var rotation = Rotation.FromAxisAngle(new Vector(1, 0, 0), 90);
        var text = AbbRequest.Move(7, false, new Vector(100.12345, -0.00001, 2.5), rotation).ToWireText();
        Assert.Equal("@7 2 100.123 0 2.5 0.7071 0.7071 0 0;", text);
    }

    [Fact]
    public void MoveAbsJ_SixJoints_MatchesOriginalWireText() =>
        Assert.Equal("@13 3 0 0 0 0 90 0;", AbbRequest.MoveAbsJ(13, new Joints(0, 0, 0, 0, 90, 0)).ToWireText());

    [Fact]
    public void SettingsRequests_UnroundedValues_MatchOriginalWireText()
    {
        Assert.Equal("@14 4 100;", AbbRequest.Speed(14, 100).ToWireText());
        Assert.Equal("@14 4 12.3456789;", AbbRequest.Speed(14, 12.3456789).ToWireText());
        Assert.Equal("@15 5 2;", AbbRequest.Zone(15, 2).ToWireText());
        Assert.Equal("@17 6 1.5;", AbbRequest.WaitTime(17, 1500).ToWireText());
        Assert.Equal("@18 7 \"Hello world!\";", AbbRequest.TPWrite(18, "Hello world!").ToWireText());
        Assert.Equal("@20 9;", AbbRequest.NoTool(20).ToWireText());
        Assert.Equal("@21 10 \"DO_15\" 1;", AbbRequest.SetDO(21, "DO_15", true).ToWireText());
        Assert.Equal("@21 10 \"DO_15\" 0;", AbbRequest.SetDO(21, "DO_15", false).ToWireText());
        Assert.Equal("@22 11 \"AO_1\" 0.5;", AbbRequest.SetAO(22, "AO_1", 0.5).ToWireText());
        Assert.Equal("@30 103 0.02;", AbbRequest.MotionUpdateInterval(30, 20).ToWireText());
    }

    [Fact]
    public void Acceleration_MillimetresPerSecondSquared_SentInMetresPerSecondSquared() =>
        Assert.Equal("@16 13 0.03;", AbbRequest.Acceleration(16, 30).ToWireText());

    [Fact]
    public void Tool_ElevenValues_MatchesOriginalWireText() =>
        Assert.Equal("@19 8 0 0 100 1 0 0 0 1 0 0 50;",
            AbbRequest.Tool(19, new Vector(0, 0, 100), Rotation.Identity, 1, new Vector(0, 0, 50)).ToWireText());

    [Fact]
    public void ExternalAxes_UnsetAxes_PrintedAs9E9()
    {
        Assert.Equal("@23 15 1800 9E9 9E9 9E9 9E9 9E9;", AbbRequest.ExternalAxesRobTarget(23, new ExternalAxes(1800)).ToWireText());
        Assert.Equal("@0 16 1.235 9E9 -5 9E9 9E9 9E9;", AbbRequest.ExternalAxesJointTarget(0, new ExternalAxes(1.23456, null, -5)).ToWireText());
    }

    [Fact]
    public void MoveC_EndAndThroughPoint_MatchesOriginalWireText()
    {
        var rotation = Rotation.FromQuaternion(0, 0.70710678, 0.70710678, 0);
        Assert.Equal("@24 30 600 600 500 0 0.7071 0.7071 0 500 600 500;",
            AbbRequest.MoveC(24, new Vector(600, 600, 500), rotation, new Vector(500, 600, 500)).ToWireText());
    }

    [Fact]
    public void Custom_Statement_SentVerbatimAfterId()
    {
        Assert.Equal("@25 18 300 0 300 1 0 0 0;", AbbRequest.Custom(25, "18 300 0 300 1 0 0 0").ToWireText());
        Assert.Equal("@26 103 0.05;", AbbRequest.Custom(26, " 103 0.05; ").ToWireText());
    }

    [Fact]
    public void Custom_StatementWithSemicolonInside_Throws() =>
        Assert.Throws<ArgumentException>(() => AbbRequest.Custom(1, "4 100; 5 2"));

    [Theory]
    [InlineData("say \"hi\"")]
    [InlineData("a;b")]
    [InlineData("line\nbreak")]
    [InlineData("café")]
    public void SetDO_SignalNameBreakingFraming_Throws(string signal) =>
        Assert.Throws<ArgumentException>(() => AbbRequest.SetDO(1, signal, true));

    [Fact]
    public void WhyStatementCannotBeSent_LongerThanTheDriverReads_IsRefused()
    {
        // Found by the extreme-value test: a million-character statement was sent, and the controller closed the link.
        string longest = "17 \"" + new string('t', 80) + "\"" + string.Concat(Enumerable.Repeat(" 0." + new string('0', 78), 11));
        longest = longest.Replace("17 ", "17" + new string(' ', 1001 - longest.Length), StringComparison.Ordinal);
        Assert.Equal(1000, longest.Length);
        Assert.Null(AbbRequest.WhyStatementCannotBeSent(longest));
        Assert.EndsWith("\"" + new string('1', 17) + "...\" is not a numeric instruction code.", AbbRequest.WhyStatementCannotBeSent(new string('1', 1000)));
        Assert.Equal("A custom ABB statement can be at most 1000 characters (what the driver reads of one request), but \"" + new string('1', 37) + "...\" has 1001.",
            AbbRequest.WhyStatementCannotBeSent(new string('1', 1001)));
        var refused = Assert.Throws<ArgumentException>(() => AbbRequest.Custom(3, new string('x', 1_000_000)));
        Assert.Equal("statement", refused.ParamName);
    }

    [Fact]
    public void TPWrite_UnsafeText_IsSanitizedAndTruncated()
    {
        Assert.Equal("@3 7 \"say 'hi', ok?\";", AbbRequest.TPWrite(3, "say \"hi\"; ok\u00e9").ToWireText());
        Assert.Equal(AbbRequest.MaxTextLength, AbbRequest.TPWrite(3, new string('x', 200)).Text!.Length);
    }

    [Theory]
    [InlineData(-1)]
    [InlineData(AbbRequest.MaxId + 1)]
    public void Constructor_IdOutsideRapidFloatRange_Throws(int id) =>
        Assert.Throws<ArgumentOutOfRangeException>(() => AbbRequest.Speed(id, 100));

    [Fact]
    public void Constructor_NaNValue_Throws() =>
        Assert.Throws<ArgumentException>(() => AbbRequest.Speed(1, double.NaN));

    [Fact]
    public void Constructor_TwelveParameters_Throws() =>
        Assert.Throws<ArgumentException>(() => new AbbRequest(1, 17, null, new double[12]));

    [Fact]
    public void ToWireText_GermanCulture_StillUsesDecimalPoint()
    {
        var previous = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            Assert.Equal("@1 4 12.5;", AbbRequest.Speed(1, 12.5).ToWireText());
        }
        finally
        {
            CultureInfo.CurrentCulture = previous;
        }
    }

    [Fact]
    public void EncodeTo_Span_WritesSameBytesAsWireText()
    {
        var request = AbbRequest.Move(8_388_608, true, new Vector(-1234.5678, 0.0004, 99999.999), Rotation.Identity);
        var buffer = new byte[request.MaxEncodedLength];
        int n = request.EncodeTo(buffer);
        Assert.Equal("@8388608 1 -1234.568 0 99999.999 1 0 0 0;", Encoding.ASCII.GetString(buffer, 0, n));
    }

    [Fact]
    public void EncodeTo_BufferTooSmall_Throws() =>
        Assert.Throws<ArgumentException>(() => AbbRequest.Speed(1, 100).EncodeTo(new byte[4]));
}

using System.Text;

namespace Machina.Tests.Brands.Abb;

public class AbbMessageReaderTests
{
    private const string Handshake = "$20 1 4 2;$21 815 0 1075 0.7071 0 0.7071 0;$22 0 0 0 0 90 0;$23 9.000E+09 9E+09 1.800E+03 9E9 9E9 9E9;";

    [Fact]
    public void TryRead_Handshake_DecodesTypedValues()
    {
        var messages = ReadAll(Handshake);
        Assert.Equal(4, messages.Count);
        Assert.Equal(new AbbDriverVersion(1, 4, 2), messages[0].ToVersion());
        var pose = messages[1].ToPose();
        Assert.Equal(new Vector(815, 0, 1075), pose.Position);
        Assert.True(pose.Rotation.IsSimilar(Rotation.FromAxisAngle(new Vector(0, 1, 0), 90), 0.01));
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), messages[2].ToJoints());
        Assert.Equal(new ExternalAxes(null, null, 1800), messages[3].ToExternalAxes());
    }

    [Fact]
    public void TryRead_Progress_DecodesLastExecutedAndLastReceivedIds()
    {
        var messages = ReadAll("$20 1 6 0;$25 17 23;$25 0 0;");
        Assert.True(messages[0].ToVersion().ReportsProgress);
        Assert.False(new AbbDriverVersion(1, 5, 0).ReportsProgress);
        Assert.Equal(new DeviceProgress(17, 23), messages[1].ToProgress());
        Assert.True(messages[1].ToProgress().IsBusy);
        Assert.True(messages[2].ToProgress().IsFresh);
        Assert.Equal("$25 17 23;", AbbMessageFormat.Progress(17, 23));
        Assert.Throws<AbbProtocolException>(() => ReadAll("$25 17;")[0].ToProgress());
    }

    [Fact]
    public void TryRead_EverySplitPoint_GivesSameMessages()
    {
        string stream = Handshake + "@1 1;@2 4;15;$24 1 2 3 1 0 0 0>4 5 6 7 8 9>9E9 9E9 9E9 9E9 9E9 9E9;";
        var expected = ReadAll(stream).Select(m => m.ToString()).ToArray();
        Assert.Equal(8, expected.Length);
        byte[] bytes = Encoding.ASCII.GetBytes(stream);
        for (int split = 0; split <= bytes.Length; split++)
        {
            var reader = new AbbMessageReader();
            var got = new List<string>();
            reader.Append(bytes.AsSpan(0, split));
            Drain(reader, got);
            reader.Append(bytes.AsSpan(split));
            Drain(reader, got);
            Assert.Equal(expected, got);
            Assert.Equal(0, reader.PendingByteCount);
        }
    }

    [Fact]
    public void TryRead_OneByteAtATime_GivesSameMessages()
    {
        var reader = new AbbMessageReader();
        var got = new List<string>();
        foreach (byte b in Encoding.ASCII.GetBytes(Handshake + "@7 3;"))
        {
            reader.Append([b]);
            Drain(reader, got);
        }
        Assert.Equal(["$20 1 4 2;", "$21 815 0 1075 0.7071 0 0.7071 0;", "$22 0 0 0 0 90 0;", "$23 9000000000 9000000000 1800 9000000000 9000000000 9000000000;", "@7 3;"], got);
    }

    [Fact]
    public void TryRead_Acknowledgements_ReturnIdAndCode()
    {
        var messages = ReadAll("@12 1;15;@8388608 16;");
        Assert.Equal(new AbbAcknowledgement(12, 1), messages[0].ToAcknowledgement());
        Assert.Equal(new AbbAcknowledgement(0, 15), messages[1].ToAcknowledgement());
        Assert.Equal(new AbbAcknowledgement(8_388_608, 16), messages[2].ToAcknowledgement());
    }

    [Fact]
    public void TryRead_MonitorChunks_DecodeFullPose()
    {
        var update = ReadAll("$24 100.5 -2 300 1 0 0 0>10 20 30 40 50 60>1.800E+03 9.000E+09 9E9 9E9 9E9 9E9;")[0].ToMonitorUpdate();
        Assert.Equal(new Vector(100.5, -2, 300), update.Position);
        Assert.Equal(Rotation.Identity, update.Rotation);
        Assert.Equal(new Joints(10, 20, 30, 40, 50, 60), update.Joints);
        Assert.Equal(new ExternalAxes(1800), update.ExternalAxes);
    }

    [Fact]
    public void TryRead_InformationReply_KeptAsText()
    {
        var message = ReadAll("$@5 101 2 192.168.125.1 7000;")[0];
        Assert.Equal((AbbMessageKind.Information, 5, 101, "2 192.168.125.1 7000"), (message.Kind, message.Id, message.Code, message.Text));
    }

    [Fact]
    public void TryRead_EmptyPiecesAndLineBreaks_AreSkipped() =>
        Assert.Equal(["@1 1;", "@2 1;"], ReadAll(";;\r\n@1 1;\n;@2 1;").Select(m => m.ToString()));

    [Theory]
    [InlineData("hello;", "hello;")]
    [InlineData("@abc 1;", "@abc 1;")]
    [InlineData("$22 0 0 zero 0 0 0;", "$22 0 0 zero 0 0 0;")]
    [InlineData("$;", "$;")]
    [InlineData("@-5 1;", "@-5 1;")]
    [InlineData("@5 1 2;", "@5 1 2;")]
    [InlineData("@5 1 ok;", "@5 1 ok;")]
    [InlineData("15 3;", "15 3;")]
    public void TryRead_Garbage_ThrowsWithReceivedText(string garbage, string received)
    {
        var reader = new AbbMessageReader();
        reader.Append(Encoding.ASCII.GetBytes(garbage));
        var e = Assert.Throws<AbbProtocolException>(() => reader.TryRead(out _));
        Assert.Equal(received, e.ReceivedText);
        Assert.IsAssignableFrom<MachinaException>(e);
    }

    [Fact]
    public void TryRead_EndlessStreamWithoutTerminator_Throws()
    {
        var reader = new AbbMessageReader();
        reader.Append(new byte[AbbMessageReader.MaxMessageLength + 1].Select(_ => (byte)'x').ToArray());
        var e = Assert.Throws<AbbProtocolException>(() => reader.TryRead(out _));
        Assert.StartsWith("xxxx", e.ReceivedText, StringComparison.Ordinal);
    }

    [Fact]
    public void ToJoints_TooFewValues_Throws()
    {
        var message = ReadAll("$22 1 2 3;")[0];
        Assert.Throws<AbbProtocolException>(() => message.ToJoints());
    }

    [Fact]
    public void IsSupported_Versions_AcceptsTheShippedMinorOrNewerOfTheSameMajor()
    {
        Assert.True(new AbbDriverVersion(1, 7, 0).IsSupported);
        Assert.True(new AbbDriverVersion(1, 7, 3).IsSupported);
        Assert.True(new AbbDriverVersion(1, 8, 0).IsSupported);
        Assert.False(new AbbDriverVersion(1, 6, 0).IsSupported); // no request 31: an arc's through point would point the tool up
        Assert.False(new AbbDriverVersion(1, 4, 2).IsSupported);
        Assert.False(new AbbDriverVersion(2, 0, 0).IsSupported);
    }

    [Fact]
    public void AbbMessageFormat_DriverMessages_ReadBackByReader()
    {
        var (pose, joints, axes) = AbbMessageFormat.MonitorChunks(new Vector(1.23456, 2, 3), Rotation.Identity, new Joints(1, 2, 3, 4, 5, 6), new ExternalAxes(12.5));
        Assert.Equal("$24 1.235 2 3 1 0 0 0>", pose);
        Assert.Equal("1 2 3 4 5 6>", joints);
        Assert.Equal("1.250E+01 9.000E+09 9.000E+09 9.000E+09 9.000E+09 9.000E+09;", axes);
        Assert.Equal(new ExternalAxes(12.5), ReadAll(pose + joints + axes)[0].ToMonitorUpdate().ExternalAxes);
        Assert.Equal("@3 1;", AbbMessageFormat.Acknowledgement(3, 1));
        Assert.Equal("15;", AbbMessageFormat.Acknowledgement(0, 15));
    }

    private static List<AbbMessage> ReadAll(string text)
    {
        var reader = new AbbMessageReader();
        reader.Append(Encoding.ASCII.GetBytes(text));
        var list = new List<AbbMessage>();
        while (reader.TryRead(out var m))
        {
            list.Add(m);
        }
        return list;
    }

    private static void Drain(AbbMessageReader reader, List<string> into)
    {
        while (reader.TryRead(out var m))
        {
            into.Add(m.ToString());
        }
    }
}

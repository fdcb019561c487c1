using System.Text;
using System.Text.RegularExpressions;
using System.Xml.Linq;

namespace Machina.Tests.Online;

/// <summary>The shipped KRL driver files (drivers/kuka): embedded, filled, and consistent with what the host sends and reads.</summary>
public class KukaDriverModulesTests
{
    private static IReadOnlyDictionary<string, string> Files(string port = "54600", string? advance = null)
    {
        var parameters = new Dictionary<string, string> { ["HOSTNAME"] = "172.31.1.147", ["PORT"] = port };
        if (advance is not null)
        {
            parameters["ADVANCE"] = advance;
        }
        return Robot.Create("Modules", "KUKA").GetDeviceDriverModules(parameters);
    }

    [Fact]
    public void GetDeviceDriverModules_Kuka_SixFilesWithHostPortsAndAdvance()
    {
        var files = Files();
        Assert.Equal(["machina_kuka_driver.dat", "machina_kuka_driver.src", "machina_kuka_monitor.dat", "machina_kuka_monitor.src", "machina_kuka_monitor.xml", "machina_kuka_server.xml"],
            files.Keys.Order(StringComparer.Ordinal));
        Assert.All(files.Values, text => Assert.DoesNotContain("{{", text, StringComparison.Ordinal));
        XElement server = XElement.Parse(files["machina_kuka_server.xml"]);
        Assert.Equal("172.31.1.147", server.Descendants("INTERNAL").Single().Element("IP")!.Value);
        Assert.Equal("54600", server.Descendants("INTERNAL").Single().Element("PORT")!.Value);
        Assert.Equal("Client", server.Descendants("EXTERNAL").Single().Element("TYPE")!.Value);
        XElement monitor = XElement.Parse(files["machina_kuka_monitor.xml"]);
        Assert.Equal("172.31.1.147", monitor.Descendants("INTERNAL").Single().Element("IP")!.Value);
        Assert.Equal("54601", monitor.Descendants("INTERNAL").Single().Element("PORT")!.Value);
        Assert.Contains("\n  $ADVANCE = 3\n", files["machina_kuka_driver.src"].ReplaceLineEndings("\n"), StringComparison.Ordinal);
        Assert.Contains("\n  $ADVANCE = 0\n", Files(advance: "0")["machina_kuka_driver.src"].ReplaceLineEndings("\n"), StringComparison.Ordinal);
    }

    /// <summary>KRL's arithmetic has +, -, * and / (issue 23): a MOD, as RAPID has, does not parse. The ring wraps with an IF instead.</summary>
    [Fact]
    public void KrlFiles_UseNoModOperator_RingWrapsWithIf()
    {
        var files = Files();
        foreach (string name in new[] { "machina_kuka_driver.src", "machina_kuka_driver.dat", "machina_kuka_monitor.src", "machina_kuka_monitor.dat" })
        {
            Assert.DoesNotMatch(new Regex(@"\bMOD\b", RegexOptions.IgnoreCase), files[name]);
        }
        string driver = files["machina_kuka_driver.src"].ReplaceLineEndings("\n");
        Assert.Contains("\n    write_slot = write_slot + 1\n    IF write_slot > 100 THEN\n      write_slot = 1\n    ENDIF\n", driver, StringComparison.Ordinal);
        Assert.Contains("\n  read_slot = read_slot + 1\n  IF read_slot > 100 THEN\n    read_slot = 1\n  ENDIF\n", driver, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("6", "ADVANCE must be a whole number from 0 to 5")]
    [InlineData("1.5", "ADVANCE must be a whole number from 0 to 5")]
    [InlineData("fast", "ADVANCE must be a whole number from 0 to 5")]
    public void GetDeviceDriverModules_BadAdvance_Explains(string advance, string expected)
    {
        var error = Assert.Throws<ArgumentException>(() => Files(advance: advance));
        Assert.Contains(expected, error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void GetDeviceDriverModules_HostThatBreaksXmlOrLastPort_Refused()
    {
        Assert.Throws<ArgumentException>(() => KukaDriverModules.Create("a<b", 7000));
        Assert.Throws<ArgumentOutOfRangeException>(() => KukaDriverModules.Create("10.0.0.1", 65534));
    }

    [Fact]
    public void ServerXml_ReceiveElements_AreTheAttributesOfTheHostsBatches()
    {
        XElement server = XElement.Parse(KukaDriverModules.Read("machina_kuka_server.xml"));
        var receive = Tags(server, "RECEIVE");
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, [new KukaInstruction(1, KukaActionCode.Message, new KukaValues(), "x"), new KukaInstruction(2, KukaActionCode.Circular, new KukaValues(), "")]);
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(sb.ToString()));
        Assert.True(reader.TryRead(out KukaElement batch));
        // Every action's attributes, then the six only a CIRC carries (V8 ... V13, its auxiliary point).
        string[] attributes = [.. batch.Children.Single().Children.SelectMany(a => a.Attributes.Select(p => $"{batch.Name}/{batch.Children[0].Name}/{a.Name}/@{p.Key}")).Distinct()];
        Assert.Equal(16, attributes.Length);
        // The batch's attributes, the batch itself (flag 2), then the host's out-of-band commands (flags 4, 5, 6: the driver's interrupts).
        string[] commands = [.. new[] { KukaProtocol.StopCommand, KukaProtocol.PauseCommand, KukaProtocol.ResumeCommand }.Select(ElementName)];
        Assert.Equal(attributes.Append("DT").Concat(commands), receive);
        string Flag(string tag) => server.Descendants("ELEMENT").Single(e => e.Attribute("Tag")!.Value == tag).Attribute("Set_Flag")!.Value;
        Assert.Equal(["2", "4", "5", "6"], new[] { "DT" }.Concat(commands).Select(Flag));
    }

    [Fact]
    public void ServerXml_SendElements_AreWhatTheHostReads()
    {
        XElement server = XElement.Parse(KukaDriverModules.Read("machina_kuka_server.xml"));
        var expected = AttributePaths(KukaMessages.State(new Joints(0, -90, 90, 0, 0, 0), new Vector(1, 2, 3), Rotation.Identity, 1, 2, "#KR6R900SIXX C4"))
            .Concat(AttributePaths(KukaMessages.ReadAcknowledgement(3, 0.5))).Concat(AttributePaths(KukaFailure.Message(4, KukaFailure.NoSpeed)))
            .Append($"{KukaProtocol.Control}/@K");
        Assert.Equal(expected, Tags(server, "SEND"));
        XElement monitor = XElement.Parse(KukaDriverModules.Read("machina_kuka_monitor.xml"));
        Assert.Equal(AttributePaths(KukaMessages.Pose(new Joints(0, -90, 90, 0, 0, 0), new Vector(1, 2, 3), Rotation.Identity)), Tags(monitor, "SEND"));
        Assert.Equal(AttributePaths(KukaMessages.MonitorRate(50)), Tags(monitor, "RECEIVE"));
    }

    [Fact]
    public void ServerXml_Buffers_HoldTheLargestBatchAndTheWholeRing()
    {
        XElement server = XElement.Parse(KukaDriverModules.Read("machina_kuka_server.xml"));
        int limit = int.Parse(server.Descendants("BUFFERING").Single().Attribute("Limit")!.Value, Num.Inv);
        int bytes = int.Parse(server.Descendants("BUFFSIZE").Single().Attribute("Limit")!.Value, Num.Inv);
        Assert.InRange(KukaProtocol.Capacity, 1, limit);
        var worst = new KukaValues();
        for (int i = 0; i < KukaProtocol.ValueCount; i++)
        {
            worst[i] = -123456.123456;
        }
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, Enumerable.Range(0, KukaProtocol.Capacity)
            .Select(i => new KukaInstruction(int.MaxValue, KukaActionCode.Message, worst, new string('&', KukaProtocol.MaxTextLength))));
        Assert.InRange(sb.Length, 1, Math.Min(bytes, KukaXmlReader.MaxElementLength));
    }

    [Fact]
    public void DriverSrc_RingVersionAndActionCodes_MatchTheHost()
    {
        string src = KukaDriverModules.Read("machina_kuka_driver.src");
        string dat = KukaDriverModules.Read("machina_kuka_driver.dat");
        string ring = KukaProtocol.Capacity.ToString(Num.Inv);
        Assert.Contains($"DECL INT slot_id[{ring}]", dat, StringComparison.Ordinal);
        Assert.Contains($"DECL CHAR slot_text[{ring},{KukaProtocol.MaxTextLength}]", dat, StringComparison.Ordinal);
        Assert.Equal(4, Regex.Matches(src, $"_slot > {ring} THEN|FOR i = 1 TO {ring}").Count);
        Assert.Contains($"\"S/@VR\", \"{KukaProtocol.DriverVersion}\"", src, StringComparison.Ordinal);
        var cases = Regex.Matches(src, @"^\s*CASE ([\d, ]+)$", RegexOptions.Multiline)
            .SelectMany(m => m.Groups[1].Value.Split(',', StringSplitOptions.TrimEntries)).Select(int.Parse).ToHashSet();
        Assert.All(Enum.GetValues<KukaActionCode>(), code => Assert.Contains((int)code, cases));
        // The KRL compiler's conventions: the INI fold, the BCO run, $ADVANCE.
        Assert.Contains("BAS (#INITMOV,0 )", src, StringComparison.Ordinal);
        Assert.Contains("PTP $AXIS_ACT", src, StringComparison.Ordinal);
    }

    private static string ElementName(string xml)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(xml));
        Assert.True(reader.TryRead(out KukaElement element));
        return element.Name;
    }

    private static List<string> Tags(XElement config, string section) =>
        [.. config.Element(section)!.Descendants("ELEMENT").Select(e => e.Attribute("Tag")!.Value)];

    private static IEnumerable<string> AttributePaths(string xml)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(xml));
        Assert.True(reader.TryRead(out KukaElement element));
        return element.Attributes.Select(a => $"{element.Name}/@{a.Key}");
    }
}

using System.Text;

namespace Machina.Tests.Online;

/// <summary>The KUKA wire format: batches written by the host (exact bytes) and the driver's XML read back however it is split.</summary>
public class KukaProtocolTests
{
    private readonly RobotCursor _cursor = new();
    private int _nextId = 1;

    /// <summary>Applies the action to the cursor with the next id and returns its A element, or "" when nothing is sent.</summary>
    private string Wire(RobotAction action)
    {
        action.Id = _nextId++;
        Assert.Null(_cursor.TryApply(action));
        KukaInstruction? instruction = KukaActionEncoder.Encode(action, action.Id, _cursor);
        if (instruction is null)
        {
            return "";
        }
        var sb = new StringBuilder();
        instruction.Value.AppendTo(sb);
        return sb.ToString();
    }

    [Fact]
    public void Encode_Motions_ExactElementsWithKukaAbcOfTheToolFrame()
    {
        Assert.Equal("<A ID=\"1\" T=\"1\" V1=\"400\" V2=\"0\" V3=\"500\" V4=\"180\" V5=\"0\" V6=\"180\" V7=\"0\" M=\"\"/>",
            Wire(new ActionTransformation(new Vector(400, 0, 500), Rotation.FlippedAroundY, false, true)));
        // KUKA's B is the turn about Y: 45° about Y is A 0, B 45, C 0.
        Assert.Equal("<A ID=\"2\" T=\"1\" V1=\"400\" V2=\"0\" V3=\"500\" V4=\"0\" V5=\"45\" V6=\"0\" V7=\"0\" M=\"\"/>",
            Wire(new ActionRotation(Rotation.FromAxisAngle(0, 1, 0, 45), false)));
        Wire(new ActionMotionMode(MotionType.Joint));
        Assert.Equal("<A ID=\"4\" T=\"2\" V1=\"400\" V2=\"0\" V3=\"450.5\" V4=\"0\" V5=\"45\" V6=\"0\" V7=\"0\" M=\"\"/>",
            Wire(new ActionTranslation(new Vector(0, 0, -49.5), true)));
        Assert.Equal("<A ID=\"5\" T=\"3\" V1=\"0\" V2=\"-90\" V3=\"90\" V4=\"0\" V5=\"0.123\" V6=\"0\" V7=\"0\" M=\"\"/>",
            Wire(new ActionAxes(new Joints(0, -90, 90, 0, 0.1234, 0), false)));
    }

    [Fact]
    public void Encode_SameRotationTwice_CursorNotChanged()
    {
        Wire(new ActionTransformation(new Vector(400, 0, 500), Rotation.FlippedAroundY, false, true));
        Rotation before = _cursor.Rotation!.Value;
        KukaActionEncoder.Encode(new ActionTranslation(new Vector(1, 0, 0), true) { Id = 9 }, 9, _cursor);
        KukaActionEncoder.Encode(new ActionTranslation(new Vector(1, 0, 0), true) { Id = 9 }, 9, _cursor);
        Assert.Equal(before, _cursor.Rotation!.Value);
    }

    [Fact]
    public void Encode_SettingsAndIO_ExactElementsInKrlUnits()
    {
        Assert.Equal("<A ID=\"1\" T=\"4\" V1=\"0.1\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionSpeed(100, false)));
        Assert.Equal("<A ID=\"2\" T=\"5\" V1=\"0.25\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionAcceleration(250, false)));
        Assert.Equal("<A ID=\"3\" T=\"5\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionAcceleration(0, false)));
        Assert.Equal("<A ID=\"4\" T=\"6\" V1=\"2\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionPrecision(2, false)));
        Assert.Equal("<A ID=\"5\" T=\"7\" V1=\"1.5\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionWait(1500)));
        Assert.Equal("<A ID=\"6\" T=\"11\" V1=\"15\" V2=\"1\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionIODigital("15", true, false)));
        Assert.Equal("<A ID=\"7\" T=\"12\" V1=\"2\" V2=\"-0.5\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionIOAnalog("2", -0.5, false)));
    }

    [Fact]
    public void Encode_Message_EscapedForXmlOneLineAndCut()
    {
        Assert.Equal("<A ID=\"1\" T=\"8\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"a &lt;b&gt; &amp; &quot;c&quot; &apos;d&apos; e f?\"/>",
            Wire(new ActionMessage("a <b> & \"c\" 'd' e\nf\u00e9")));
        string text = Wire(new ActionMessage(new string('x', 100)));
        Assert.Contains("M=\"" + new string('x', 80) + "\"/>", text, StringComparison.Ordinal);
    }

    [Fact]
    public void Encode_ToolsAndPop_FrameSettingsOrNothing()
    {
        Assert.Equal("", Wire(new ActionDefineTool(Tool.Create("pen", new Vector(0, 0, 100), Rotation.FromAxisAngle(0, 0, 1, 90), 1, new Vector(0, 0, 50)))));
        Assert.Equal("<A ID=\"2\" T=\"9\" V1=\"0\" V2=\"0\" V3=\"100\" V4=\"90\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionAttachTool("pen")));
        Assert.Equal("<A ID=\"3\" T=\"10\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionDetachTool()));
        Assert.Equal("", Wire(new ActionPushPop(true)));
        Wire(new ActionSpeed(100, false));
        // Restored: 20 mm/s, the default acceleration (the controller's own, 0) and 5 mm.
        Assert.Equal("<A ID=\"6\" T=\"13\" V1=\"0.02\" V2=\"0\" V3=\"5\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>", Wire(new ActionPushPop(false)));
        Assert.Equal("", Wire(new ActionPushPop(true)));
        Assert.Equal("", Wire(new ActionPushPop(false)));
        Assert.Equal("", Wire(new ActionComment("only Machina sees this")));
    }

    [Fact]
    public void AppendBatch_TwoActions_OneDtElement()
    {
        var v = new KukaValues();
        v[0] = 1.5;
        var sb = new StringBuilder();
        KukaInstruction.AppendBatch(sb, [new KukaInstruction(7, KukaActionCode.Wait, v, ""), new KukaInstruction(8, KukaActionCode.Message, new KukaValues(), "hi")]);
        Assert.Equal("<DT><DR><A ID=\"7\" T=\"7\" V1=\"1.5\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/>"
            + "<A ID=\"8\" T=\"8\" V1=\"0\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"hi\"/></DR></DT>", sb.ToString());
    }

    public static TheoryData<RobotAction, string> Refused => new()
    {
        { new ActionExternalAxis(1, 100, ExternalAxesTarget.All, false), "ExternalAxis" },
        { new ActionArmAngle(10, false), "ArmAngle" },
        { new ActionCustomCode("$OUT[1] = TRUE", false), "CustomCode" },
        { new ActionCustomCode("DECL INT i", true), "CustomCode" },
        { new ActionTemperature(200, RobotPartType.Extruder, false, false), "Temperature" },
        { new ActionExtrusion(true), "Extrusion" },
        { new ActionExtrusionRate(10, false), "ExtrusionRate" },
        { new ActionIODigital("DO_gripper", true, false), "signal name" },
        { new ActionIODigital("1", true, true), "tool outputs" },
        { new ActionIODigital("5000", true, false), "numbered 1 to 4096" },
        { new ActionIODigital("0", true, false), "numbered 1 to 4096" },
        { new ActionIOAnalog("33", 0.5, false), "numbered 1 to 32" },
        { new ActionIOAnalog("1", 2, false), "from -1 to 1" },
    };

    [Theory]
    [MemberData(nameof(Refused))]
    public void WhyCannotStream_ActionTheDriverCannotRun_NamesItAndSaysKuka(RobotAction action, string reason)
    {
        string? why = new KukaOnline().WhyCannotStream(action);
        Assert.NotNull(why);
        Assert.StartsWith($"{action.Type} ({action.ToInstruction()}) is not supported online on KUKA: ", why, StringComparison.Ordinal);
        Assert.Contains(reason, why, StringComparison.Ordinal);
        Assert.Throws<NotSupportedException>(() => KukaActionEncoder.Encode(action, 1, _cursor));
    }

    [Fact]
    public void WhyCannotStream_ActionsTheDriverRuns_Null()
    {
        var online = new KukaOnline();
        RobotAction[] fine =
        [
            new ActionTranslation(new Vector(1, 0, 0), true), new ActionRotation(Rotation.Identity, true), new ActionAxes(new Joints(0, -90, 90, 0, 0, 0), false),
            new ActionSpeed(10, true), new ActionAcceleration(10, true), new ActionPrecision(1, true), new ActionWait(1), new ActionMessage("<&>"),
            new ActionDetachTool(), new ActionIODigital("4096", false, false), new ActionIOAnalog("32", -1, false), new ActionPushPop(true),
            new ActionComment("x"), new ActionMotionMode(MotionType.Joint), new ActionCoordinates(ReferenceCS.Local),
        ];
        Assert.All(fine, a => Assert.Null(online.WhyCannotStream(a)));
    }

    [Fact]
    public void Reader_TwoAcknowledgementsInOneRead_BothRead()
    {
        var reader = new KukaXmlReader();
        reader.Append("<R ID=\"1\"></R><R ID=\"2\"/>"u8);
        Assert.Equal([1, 2], ReadAll(reader).Select(e => e.Integer("ID")));
        Assert.Equal(0, reader.PendingByteCount);
    }

    [Fact]
    public void Reader_ElementsSplitAtEveryByte_ReadOnceComplete()
    {
        byte[] bytes = Encoding.ASCII.GetBytes("<?xml version=\"1.0\"?>\r\n<S VR=\"2.0\" A1=\"0\" A2=\"-90\" A3=\"90\" A4=\"0\" A5=\"0\" A6=\"0\" X=\"455\" Y=\"0\" Z=\"935\" A=\"0\" B=\"90\" C=\"0\" Executed=\"3\" Received=\"5\"></S>\r\n<!-- c --><R ID='12'>  </R>");
        var reader = new KukaXmlReader();
        var read = new List<KukaElement>();
        for (int i = 0; i < bytes.Length; i++)
        {
            reader.Append(bytes.AsSpan(i, 1));
            read.AddRange(ReadAll(reader));
            if (i < bytes.Length - 1)
            {
                Assert.True(read.Count < 2);
            }
        }
        Assert.Equal(["S", "R"], read.Select(e => e.Name));
        KukaState state = KukaState.Parse(read[0]);
        Assert.Equal("2.0", state.Version);
        Assert.Equal(new Joints(0, -90, 90, 0, 0, 0), state.Axes);
        Assert.Equal(new Vector(455, 0, 935), state.Position);
        Assert.Equal(new DeviceProgress(3, 5), state.Progress);
        Assert.Equal(12, read[1].Integer("ID"));
    }

    [Fact]
    public void Reader_EntitiesAndNesting_Decoded()
    {
        var reader = new KukaXmlReader();
        reader.Append("<DT><DR><A ID=\"1\" M=\"&lt;&amp;&quot;&#65;&#x42;\"/><A ID=\"2\" M=''/></DR></DT>"u8);
        KukaElement batch = Assert.Single(ReadAll(reader));
        KukaElement[] actions = [.. batch.Children.Single().Children];
        Assert.Equal("<&\"AB", actions[0].Attribute("M"));
        Assert.Equal("", actions[1].Attribute("M"));
    }

    [Theory]
    [InlineData("hello", "outside an XML element")]
    [InlineData("<R ID=\"1\"></S>", "closed by </S>")]
    [InlineData("<R ID=1></R>", "not quoted")]
    [InlineData("<R ID=\"&bogus;\"></R>", "unknown XML entity")]
    [InlineData("<1R/>", "without an element name")]
    public void Reader_Garbage_ProtocolErrorWithText(string garbage, string expected)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(garbage));
        var error = Assert.Throws<KukaProtocolException>(() => ReadAll(reader));
        Assert.Contains(expected, error.Message, StringComparison.Ordinal);
        Assert.Equal(garbage, error.ReceivedText);
    }

    [Fact]
    public void Reader_ElementNeverEnds_BoundedBuffer()
    {
        var reader = new KukaXmlReader();
        reader.Append("<R ID=\"1\">"u8);
        byte[] filler = Encoding.ASCII.GetBytes(new string('x', 4096));
        var error = Assert.Throws<KukaProtocolException>(() =>
        {
            for (int i = 0; i < 20; i++)
            {
                reader.Append(filler);
                ReadAll(reader);
            }
        });
        Assert.Contains($"more than {KukaXmlReader.MaxElementLength} bytes", error.Message, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("<S VR=\"2.0\"></S>", "has no attribute A1")]
    [InlineData("<R ID=\"one\"></R>", "not a whole number")]
    public void Parse_MissingOrMalformedAttribute_ProtocolError(string xml, string expected)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(xml));
        KukaElement element = Assert.Single(ReadAll(reader));
        var error = Assert.Throws<KukaProtocolException>(() => element.Name == "S" ? KukaState.Parse(element).Version : element.Integer("ID").ToString(Num.Inv));
        Assert.Contains(expected, error.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Messages_StateRoundTrip_SamePoseAndProgress()
    {
        Rotation down = Rotation.FromAxisAngle(0, 1, 0, 90);
        string xml = KukaMessages.State(new Joints(0, -90, 90, 0, 0, 0), new Vector(455, 0, 935), down, 7, 9);
        Assert.Equal("<S VR=\"2.1\" A1=\"0\" A2=\"-90\" A3=\"90\" A4=\"0\" A5=\"0\" A6=\"0\" X=\"455\" Y=\"0\" Z=\"935\" A=\"0\" B=\"90\" C=\"0\" Executed=\"7\" Received=\"9\"></S>", xml);
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(xml));
        KukaState state = KukaState.Parse(Assert.Single(ReadAll(reader)));
        Assert.True(state.Rotation.AngleTo(down) < 1e-6);
        Assert.Equal("<R ID=\"42\"></R>", KukaMessages.Acknowledgement(42));
        Assert.Equal("<MON Ms=\"20\"/>", KukaMessages.MonitorRate(50));
    }

    private static List<KukaElement> ReadAll(KukaXmlReader reader)
    {
        var list = new List<KukaElement>();
        while (reader.TryRead(out KukaElement element))
        {
            list.Add(element);
        }
        return list;
    }
}

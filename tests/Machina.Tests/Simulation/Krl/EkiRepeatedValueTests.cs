using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// perf54e: the EthernetKRL splitter hands an attribute's value again as the same string while the same characters arrive (a
/// stream repeats most of an action's values), and a flat SEND document is written in a buffer the channel keeps. Guards that
/// the values and the documents stay what they were: a changed value is the new text, an entity is decoded every time, a value
/// is never handed to another attribute, and the document's text is the builder's.
/// </summary>
public sealed class EkiRepeatedValueTests
{
    private static List<(string Tag, string Value)> Split(params string[] chunks)
    {
        var splitter = new EkiXmlSplitter();
        var values = new List<(string Tag, string Value)>();
        splitter.Value += (tag, value) => values.Add((tag, value));
        foreach (string chunk in chunks)
        {
            splitter.Append(chunk);
        }
        return values;
    }

    [Fact]
    public void SameCharacters_SameString_ChangedCharacters_TheNewText()
    {
        List<(string Tag, string Value)> values = Split(
            "<DT><DR><A ID=\"1\" T=\"1\" V4=\"180.000000\" M=\"\"/></DR></DT>",
            "<DT><DR><A ID=\"2\" T=\"1\" V4=\"180.000000\" M=\"\"/></DR></DT>",
            "<DT><DR><A ID=\"3\" T=\"2\" V4=\"180.000001\" M=\"x\"/></DR></DT>");

        Assert.Equal(
            [
                ("DT/DR/A/@ID", "1"), ("DT/DR/A/@T", "1"), ("DT/DR/A/@V4", "180.000000"), ("DT/DR/A/@M", ""),
                ("DT/DR/A/@ID", "2"), ("DT/DR/A/@T", "1"), ("DT/DR/A/@V4", "180.000000"), ("DT/DR/A/@M", ""),
                ("DT/DR/A/@ID", "3"), ("DT/DR/A/@T", "2"), ("DT/DR/A/@V4", "180.000001"), ("DT/DR/A/@M", "x"),
            ],
            values);
        Assert.Same(values[1].Value, values[5].Value); // T="1" twice: one string
        Assert.Same(values[2].Value, values[6].Value); // V4 the same: one string
        Assert.NotSame(values[0].Value, values[4].Value);
    }

    [Fact]
    public void ValueOfAnotherAttribute_NotHandedAcross()
    {
        // V1's last value is "5"; V2 then arrives with "5": equal text, its own attribute's string (never V1's).
        List<(string Tag, string Value)> values = Split("<A V1=\"5\" V2=\"6\"/>", "<A V1=\"7\" V2=\"5\"/>");

        Assert.Equal([("A/@V1", "5"), ("A/@V2", "6"), ("A/@V1", "7"), ("A/@V2", "5")], values);
        Assert.NotSame(values[0].Value, values[3].Value);
    }

    [Fact]
    public void Entities_DecodedEveryTime()
    {
        List<(string Tag, string Value)> values = Split("<A M=\"a &amp; b\"/>", "<A M=\"a &amp; b\"/>", "<A M=\"&lt;&gt;\"/>");

        Assert.Equal([("A/@M", "a & b"), ("A/@M", "a & b"), ("A/@M", "<>")], values);
    }

    [Fact]
    public void ValueSplitAcrossChunks_SameText()
    {
        List<(string Tag, string Value)> values = Split("<A V=\"12.5\"/><A V=\"12", ".5\"/><A V=\"12.5\"/>");

        Assert.Equal([("A/@V", "12.5"), ("A/@V", "12.5"), ("A/@V", "12.5")], values);
    }

    [Fact]
    public void FlatDocument_InAKeptBuffer_SameTextAsBefore_AndTheBufferGrows()
    {
        string[] attributes = ["R/@ID", "R/@V"];
        var values = new Dictionary<string, string>(StringComparer.Ordinal) { ["R/@ID"] = "17" };
        char[] scratch = new char[4];

        string first = EkiSendDocument.WriteFlat("R", attributes, values, ref scratch);
        values["R/@V"] = "a\"<&>";
        string second = EkiSendDocument.WriteFlat("R", attributes, values, ref scratch);
        values["R/@ID"] = "18";
        string third = EkiSendDocument.WriteFlat("R", attributes, values);

        Assert.Equal("<R ID=\"17\" />", first);
        Assert.Equal("<R ID=\"17\" V=\"a&quot;&lt;&amp;&gt;\" />", second);
        Assert.Equal("<R ID=\"18\" V=\"a&quot;&lt;&amp;&gt;\" />", third);
        Assert.True(scratch.Length >= second.Length);
    }

    private const string OrderConfiguration = """
        <ETHERNETKRL>
          <CONFIGURATION>
            <EXTERNAL><TYPE>Client</TYPE></EXTERNAL>
            <INTERNAL><IP>127.0.0.1</IP><PORT>0</PORT><PROTOCOL>UDP</PROTOCOL><BUFFERING Mode="FIFO" Limit="64" /></INTERNAL>
          </CONFIGURATION>
          <RECEIVE>
            <XML>
              <ELEMENT Tag="Cmd/A/@X" Type="INT" />
              <ELEMENT Tag="Cmd/B/@Y" Type="INT" />
              <ELEMENT Tag="Cmd/C/@Z" Type="INT" />
              <ELEMENT Tag="Cmd" Set_Flag="2" />
            </XML>
          </RECEIVE>
          <SEND>
            <XML>
              <ELEMENT Tag="State/@Left" />
            </XML>
          </SEND>
        </ETHERNETKRL>
        """;

    private const string OrderProgram = """
        DEF order( )
          DECL EKI_STATUS ret
          ret = EKI_Init("Order")
          ret = EKI_Open("Order")
          WAIT FOR $FLAG[2]
          ret = EKI_GetInt("Order", "Cmd/A/@X", vals[1])
          ret = EKI_GetInt("Order", "Cmd/B/@Y", vals[2])
          ret = EKI_GetInt("Order", "Cmd/C/@Z", vals[3])
          ret = EKI_GetInt("Order", "Cmd/C/@Z", vals[4])
          ret = EKI_GetInt("Order", "Cmd/B/@Y", vals[5])
          ret = EKI_GetInt("Order", "Cmd/A/@X", vals[6])
          ret = EKI_GetInt("Order", "Cmd/B/@Y", vals[7])
          ret = EKI_GetInt("Order", "Cmd/A/@X", vals[8])
          ret = EKI_CheckBuffer("Order", "Cmd/C/@Z")
          ret = EKI_GetInt("Order", "Cmd/C/@Z", vals[9])
          ret = EKI_SetInt("Order", "State/@Left", ret.Buff)
          ret = EKI_Send("Order", "State")
          ret = EKI_Close("Order")
        END
        """;

    [Fact]
    public async Task TagsNamedInAnotherOrder_EachTakesFromItsOwnMemory()
    {
        // The channel looks a named tag up from the entry after the one found last (perf54e): a program that changes its order
        // (forwards, backwards, skipping) still takes each tag's values from that tag's memory, in order.
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Order", OrderConfiguration);
        twin.Load(("order.src", OrderProgram), ("order.dat", "DEFDAT order\n  DECL INT vals[9]\nENDDAT\n"));
        string document = "<Cmd><A X=\"1\"/><B Y=\"2\"/><C Z=\"3\"/><A X=\"4\"/><B Y=\"5\"/><C Z=\"6\"/><A X=\"7\"/><B Y=\"8\"/><C Z=\"9\"/></Cmd>";

        (KrlProgramState state, string answer) = await EkiUdpExchange.RunAsync(twin, "Order", document);

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        Assert.Equal("<State Left=\"0\" />", answer);
        object[] read = ((KrlArrayValue)twin.Modules["order"].Data["vals"].Value).ToObjects();
        Assert.Equal([1, 2, 3, 6, 5, 4, 8, 7, 9], read.Select(v => (int)v));
    }
}

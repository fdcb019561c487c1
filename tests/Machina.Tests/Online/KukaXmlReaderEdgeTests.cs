using System.Text;

namespace Machina.Tests.Online;

/// <summary>
/// The KUKA XML reader at its edges, with exact elements and messages (the gaps mutation testing found): pieces appended before
/// earlier ones are read, the buffer's growth and its bound, nesting depth, every malformed form and every entity edge.
/// </summary>
public class KukaXmlReaderEdgeTests
{
    private static List<KukaElement> ReadAll(KukaXmlReader reader)
    {
        var list = new List<KukaElement>();
        while (reader.TryRead(out KukaElement element))
        {
            list.Add(element);
        }
        return list;
    }

    private static KukaElement ReadOne(string xml)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.UTF8.GetBytes(xml));
        KukaElement element = Assert.Single(ReadAll(reader));
        Assert.Equal(0, reader.PendingByteCount);
        return element;
    }

    private static KukaProtocolException Refused(string xml)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.UTF8.GetBytes(xml));
        return Assert.Throws<KukaProtocolException>(() => ReadAll(reader));
    }

    /// <summary>Name, attributes, text and children as one line, to compare whole elements exactly.</summary>
    private static string Show(KukaElement e) =>
        e.Name + "(" + string.Join(",", e.Attributes.Select(a => a.Key + "=" + a.Value)) + ")[" + e.Text + "]{" + string.Join(";", e.Children.Select(Show)) + "}";

    [Theory]
    [InlineData("<R ID=\"1\" X='a\"b'/>", "R(ID=1,X=a\"b)[]{}")]
    [InlineData("<R ID = \"1\"\tY=\r\n'2' ></R >", "R(ID=1,Y=2)[]{}")]
    [InlineData("<a_b-c.d:e/>", "a_b-c.d:e()[]{}")]
    [InlineData("<R9/>", "R9()[]{}")]
    [InlineData("<M>  a &amp; b &gt; c&apos;&quot;  </M>", "M()[a & b > c'\"]{}")]
    [InlineData("<M>x<!-- note --><C/>y</M>", "M()[xy]{C()[]{}}")]
    [InlineData("<M A='&#00000065;'/>", "M(A=A)[]{}")]
    [InlineData("<M A='&#x41;&#X42;&#x10FFFF;&#xD7FF;&#xE000;'/>", "M(A=AB\U0010FFFF\uD7FF\uE000)[]{}")]
    [InlineData("<M A='é'/>", "M(A=é)[]{}")]
    public void Element_ReadExactly(string xml, string expected) => Assert.Equal(expected, Show(ReadOne(xml)));

    [Fact]
    public void DeclarationCommentsAndWhitespace_BetweenElements_Skipped()
    {
        var reader = new KukaXmlReader();
        reader.Append("\0 \t\r\n<?xml version=\"1.0\"?><!-- a --> <R ID=\"1\"/>\n<!-- b --><?x?><R ID=\"2\"/>  "u8);
        Assert.Equal(["R(ID=1)[]{}", "R(ID=2)[]{}"], ReadAll(reader).Select(Show));
        Assert.Equal(2, reader.PendingByteCount); // the trailing spaces wait for the next element
    }

    [Fact]
    public void EightLevels_Read_NineRefused()
    {
        string Nested(int levels) => string.Concat(Enumerable.Range(0, levels).Select(i => $"<E{i}>")) + string.Concat(Enumerable.Range(0, levels).Reverse().Select(i => $"</E{i}>"));
        Assert.Equal("E0()[]{E1()[]{E2()[]{E3()[]{E4()[]{E5()[]{E6()[]{E7()[]{}}}}}}}}", Show(ReadOne(Nested(8))));
        KukaProtocolException e = Refused(Nested(9));
        Assert.Equal("The controller sent XML nested more than 8 levels deep.", e.Message);
        Assert.Equal(Nested(9), e.ReceivedText);
    }

    [Theory]
    [InlineData("hello", "The controller sent text outside an XML element: this is not the Machina KUKA driver protocol.")]
    [InlineData("<R /x>", "The element <R> is malformed ('/' not followed by '>').")]
    [InlineData("<R ID=\"1\"X=\"2\"/>", "The element <R> is malformed (attributes must be separated by spaces).")]
    [InlineData("<R ID />", "The attribute ID of <R> has no value.")]
    [InlineData("<R ID=1/>", "The value of attribute ID of <R> is not quoted.")]
    [InlineData("<R M=\"a<b\"/>", "The value of attribute M of <R> contains '<'.")]
    [InlineData("<R M=\"<b\"/>", "The value of attribute M of <R> contains '<'.")]
    [InlineData("<R></S>", "The element <R> is closed by </S>.")]
    [InlineData("<R></R x>", "The element <R> is closed by </R>.")]
    [InlineData("<>", "The controller sent '<' without an element name after it.")]
    [InlineData("< R/>", "The controller sent '<' without an element name after it.")]
    [InlineData("<1R/>", "The controller sent '<' without an element name after it.")]
    [InlineData("<R =\"1\"/>", "The controller sent '<' without an element name after it.")]
    [InlineData("<R></> ", "The controller sent '<' without an element name after it.")]
    [InlineData("<R>a & b</R>", "The controller sent an '&' that does not start an XML entity.")]
    [InlineData("<R M='&'/>", "The controller sent an '&' that does not start an XML entity.")]
    [InlineData("<R M='&#000000065;'/>", "The controller sent an '&' that does not start an XML entity.")]
    [InlineData("<R M='&bogus;'/>", "The controller sent the unknown XML entity &bogus;.")]
    [InlineData("<R M='&#0;'/>", "The controller sent the unknown XML entity &#0;.")]
    [InlineData("<R M='&#x110000;'/>", "The controller sent the unknown XML entity &#x110000;.")]
    [InlineData("<R M='&#xD800;'/>", "The controller sent the unknown XML entity &#xD800;.")]
    [InlineData("<R M='&#xDFFF;'/>", "The controller sent the unknown XML entity &#xDFFF;.")]
    [InlineData("<R M='&#-5;'/>", "The controller sent the unknown XML entity &#-5;.")]
    [InlineData("<R M='&#;'/>", "The controller sent the unknown XML entity &#;.")]
    [InlineData("<R M='&#65x;'/>", "The controller sent the unknown XML entity &#65x;.")]
    [InlineData("<R M='&x41;'/>", "The controller sent the unknown XML entity &x41;.")]
    [InlineData("<R>&lt</R>", "The controller sent an '&' that does not start an XML entity.")]
    public void Malformed_RefusedWithTheExactReasonAndText(string xml, string message)
    {
        KukaProtocolException e = Refused(xml);
        Assert.Equal(message, e.Message);
        Assert.Equal(xml, e.ReceivedText);
    }

    [Fact]
    public void Refused_ReceivedTextIsThe200BytesFromTheFault_ThenTheReaderStartsAfresh()
    {
        var reader = new KukaXmlReader();
        string garbage = "x" + new string('y', 300);
        reader.Append(Encoding.ASCII.GetBytes("<R ID=\"1\"/>" + garbage));
        Assert.True(reader.TryRead(out KukaElement first));
        Assert.Equal("R(ID=1)[]{}", Show(first));
        KukaProtocolException e = Assert.Throws<KukaProtocolException>(() => reader.TryRead(out _));
        Assert.Equal(garbage[..200], e.ReceivedText);
        Assert.Equal(0, reader.PendingByteCount);
        reader.Append("<R ID=\"2\"/>"u8);
        Assert.Equal(["R(ID=2)[]{}"], ReadAll(reader).Select(Show));
    }

    [Theory]
    [InlineData("<", "R ID='1'/>", "R(ID=1)[]{}")]
    [InlineData("<!", "-- c --><R/>", "R()[]{}")]
    [InlineData("<!-", "- c --><R/>", "R()[]{}")]
    [InlineData("<!-- a -", "-><R/>", "R()[]{}")]
    [InlineData("<?xml ?", "><R/>", "R()[]{}")]
    [InlineData("<R", "/>", "R()[]{}")]
    [InlineData("<R ", "/>", "R()[]{}")]
    [InlineData("<R /", ">", "R()[]{}")]
    [InlineData("<R ID", "='1'/>", "R(ID=1)[]{}")]
    [InlineData("<R ID ", "= '1'/>", "R(ID=1)[]{}")]
    [InlineData("<R ID=", "'1'/>", "R(ID=1)[]{}")]
    [InlineData("<R ID= ", "'1'/>", "R(ID=1)[]{}")]
    [InlineData("<R ID='1", "'/>", "R(ID=1)[]{}")]
    [InlineData("<R ID='1'", "/>", "R(ID=1)[]{}")]
    [InlineData("<R>", "</R>", "R()[]{}")]
    [InlineData("<R>text", "</R>", "R()[text]{}")]
    [InlineData("<R><", "C/></R>", "R()[]{C()[]{}}")]
    [InlineData("<R></", "R>", "R()[]{}")]
    [InlineData("<R></R", ">", "R()[]{}")]
    [InlineData("<R></R ", ">", "R()[]{}")]
    [InlineData("<R><!-- x", " --></R>", "R()[]{}")]
    [InlineData("<R><C/>", "</R>", "R()[]{C()[]{}}")]
    public void Incomplete_WaitsThenReadsOnceTheRestArrives(string start, string rest, string expected)
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(start));
        Assert.False(reader.TryRead(out _));
        Assert.Equal(start.Length, reader.PendingByteCount);
        reader.Append(Encoding.ASCII.GetBytes(rest));
        Assert.Equal([expected], ReadAll(reader).Select(Show));
        Assert.Equal(0, reader.PendingByteCount);
    }

    [Fact]
    public void PiecesAppendedBeforeEarlierOnesAreRead_BufferMovesAndGrows_NothingLost()
    {
        var reader = new KukaXmlReader();
        var expected = new List<string>();
        var read = new List<string>();
        var stream = new StringBuilder();
        for (int i = 1; i <= 150; i++)
        {
            stream.Append(System.Globalization.CultureInfo.InvariantCulture, $"<R ID=\"{i}\" M=\"{new string('m', i % 37)}\"/>");
            expected.Add(i.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
        byte[] bytes = Encoding.ASCII.GetBytes(stream.ToString());
        int at = 0;
        int piece = 1;
        while (at < bytes.Length)
        {
            // Pieces of 1 to 700 bytes; every other piece is appended without reading first.
            int length = Math.Min(bytes.Length - at, piece * 97 % 700 + 1);
            reader.Append(bytes.AsSpan(at, length));
            at += length;
            if (piece++ % 2 == 0)
            {
                read.AddRange(ReadAll(reader).Select(e => e.Attribute("ID")!));
            }
        }
        read.AddRange(ReadAll(reader).Select(e => e.Attribute("ID")!));
        Assert.Equal(expected, read);
        Assert.Equal(0, reader.PendingByteCount);
    }

    [Fact]
    public void LargeElementInOneAppend_AfterAPartialOne_Read()
    {
        var reader = new KukaXmlReader();
        reader.Append("<R ID='1'/><R ID="u8);
        Assert.Equal(["R(ID=1)[]{}"], ReadAll(reader).Select(Show));
        string value = new('v', 5_000);
        reader.Append(Encoding.ASCII.GetBytes($"'2' M='{value}'/><R ID='3'/>"));
        Assert.Equal([$"R(ID=2,M={value})[]{{}}", "R(ID=3)[]{}"], ReadAll(reader).Select(Show));
    }

    [Fact]
    public void PendingAtTheBound_Waits_OneByteMore_Refused()
    {
        var reader = new KukaXmlReader();
        byte[] start = "<R M='"u8.ToArray();
        reader.Append(start);
        reader.Append(Encoding.ASCII.GetBytes(new string('a', KukaXmlReader.MaxElementLength - start.Length)));
        Assert.False(reader.TryRead(out _));
        Assert.Equal(KukaXmlReader.MaxElementLength, reader.PendingByteCount);
        reader.Append("a"u8);
        KukaProtocolException e = Assert.Throws<KukaProtocolException>(() => reader.TryRead(out _));
        Assert.Equal($"The controller sent more than {KukaXmlReader.MaxElementLength} bytes without completing an XML element: this is not the Machina KUKA driver protocol.", e.Message);
        Assert.Equal("<R M='" + new string('a', 194), e.ReceivedText);
        Assert.Equal(0, reader.PendingByteCount);
    }

    [Fact]
    public void PendingAtTheBound_AfterAnElementWasRead_CountsOnlyWhatIsLeft()
    {
        // One piece: a whole element, then the start of the next with exactly the bound's worth of bytes. Reading the first
        // element moves the buffer's start; the bound applies to the bytes left, not to where they sit in the buffer.
        byte[] first = "<R ID=\"1\"/>"u8.ToArray();
        byte[] next = "<R M='"u8.ToArray();
        var piece = new List<byte>(first);
        piece.AddRange(next);
        piece.AddRange(Encoding.ASCII.GetBytes(new string('a', KukaXmlReader.MaxElementLength - next.Length)));
        var reader = new KukaXmlReader();
        reader.Append(piece.ToArray());
        Assert.True(reader.TryRead(out KukaElement element));
        Assert.Equal("R(ID=1)[]{}", Show(element));
        Assert.False(reader.TryRead(out _));
        Assert.Equal(KukaXmlReader.MaxElementLength, reader.PendingByteCount);
    }

    [Fact]
    public void GarbageAfterAnElement_QuotesOnlyTheBytesLeft()
    {
        var reader = new KukaXmlReader();
        reader.Append("<R ID=\"1\"/>junk"u8);
        Assert.True(reader.TryRead(out KukaElement element));
        Assert.Equal("R(ID=1)[]{}", Show(element));
        KukaProtocolException e = Assert.Throws<KukaProtocolException>(() => reader.TryRead(out _));
        Assert.Equal("The controller sent text outside an XML element: this is not the Machina KUKA driver protocol.", e.Message);
        Assert.Equal("junk", e.ReceivedText);
        Assert.Equal(0, reader.PendingByteCount);
    }

    [Fact]
    public void ElementCompletedByAPieceWithoutGreaterThan_ReadWhenItsEndArrives()
    {
        // The element's last '>' comes in a later piece than its '/': the reader reads it then, not before.
        var reader = new KukaXmlReader();
        reader.Append("<R ID='1' "u8);
        Assert.False(reader.TryRead(out _));
        reader.Append("/"u8);
        Assert.False(reader.TryRead(out _));
        reader.Append(">"u8);
        Assert.True(reader.TryRead(out KukaElement element));
        Assert.Equal("R(ID=1)[]{}", Show(element));
    }
}

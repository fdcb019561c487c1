using System.Text;

namespace Machina.Tests.Online;

/// <summary>
/// The host reads one acknowledgement per streamed action (<c>&lt;R ID="…"&gt;&lt;/R&gt;</c>): its element, its one attribute and the id's
/// text are all it allocates (known names are the protocol's strings; the attributes are gathered in one list per reader). It made
/// lists, builders and strings of about 0.5 KB per acknowledgement. Nested elements keep their own attributes.
/// </summary>
public class KukaAcknowledgementReadTests
{
    [Fact]
    public void Read_Acknowledgements_AllocateTheElementAndItsIdOnly()
    {
        var reader = new KukaXmlReader();
        byte[][] acknowledgements = [.. Enumerable.Range(1000, 300).Select(i => Encoding.ASCII.GetBytes($"<R ID=\"{i}\"></R>"))];
        for (int i = 0; i < 100; i++)
        {
            reader.Append(acknowledgements[i]);
            Assert.True(reader.TryRead(out _));
        }

        long ids = 0;
        long before = GC.GetAllocatedBytesForCurrentThread();
        for (int i = 100; i < 300; i++)
        {
            reader.Append(acknowledgements[i]);
            reader.TryRead(out KukaElement element);
            ids += element.Integer("ID");
        }
        long perAcknowledgement = (GC.GetAllocatedBytesForCurrentThread() - before) / 200;

        Assert.True(perAcknowledgement < 160, $"{perAcknowledgement} bytes per acknowledgement");
        Assert.Equal(Enumerable.Range(1100, 200).Sum(), ids);
        Assert.False(reader.TryRead(out _));
    }

    [Fact]
    public void Read_NestedElements_EachKeepsItsOwnAttributesChildrenAndText()
    {
        var reader = new KukaXmlReader();
        reader.Append("<DT V='1'><DR K=\"2\" T='x'><A ID='3' T='4'/><A ID=\"5\" M='a&amp;b'> y </A></DR></DT><R ID=\"6\"></R>"u8);

        Assert.True(reader.TryRead(out KukaElement batch));
        Assert.True(reader.TryRead(out KukaElement acknowledgement));

        Assert.Equal("DT(V=1)[]{DR(K=2,T=x)[]{A(ID=3,T=4)[]{};A(ID=5,M=a&b)[y]{}}}", Show(batch));
        Assert.Equal("R(ID=6)[]{}", Show(acknowledgement));
        Assert.Same(KukaProtocol.Acknowledgement, acknowledgement.Name);
    }

    private static string Show(KukaElement e) =>
        e.Name + "(" + string.Join(",", e.Attributes.Select(a => a.Key + "=" + a.Value)) + ")[" + e.Text + "]{" + string.Join(";", e.Children.Select(Show)) + "}";
}

using System.Text;
using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// perf56e: EKI_Send of an element of attributes only (the driver's acknowledgement, once an action) goes from the channel's
/// scratch to its UTF-8 bytes without a string in between. Guards that the bytes are the text's, whatever the values hold and
/// however the scratch grows, and that the send makes the byte array and nothing else.
/// </summary>
public sealed class EkiSendBytesTests
{
    [Fact]
    public void FlatDocumentBytes_AreTheTextsUtf8_WithEscapesAndCharactersAbove127_AndTheScratchGrows()
    {
        string[] attributes = ["R/@ID", "R/@V"];
        var values = new Dictionary<string, string>(StringComparer.Ordinal) { ["R/@ID"] = "17" };
        char[] scratch = new char[4];

        byte[] first = EkiSendDocument.WriteFlatBytes("R", attributes, values, ref scratch);
        values["R/@V"] = "é\"<&>ü";
        byte[] second = EkiSendDocument.WriteFlatBytes("R", attributes, values, ref scratch);

        Assert.Equal("<R ID=\"17\" />"u8.ToArray(), first);
        Assert.Equal(Encoding.UTF8.GetBytes("<R ID=\"17\" V=\"é&quot;&lt;&amp;&gt;ü\" />"), second);
        Assert.Equal(Encoding.UTF8.GetBytes(EkiSendDocument.WriteFlat("R", attributes, values)), second);
        Assert.Equal(41, second.Length); // 39 characters: é and ü take two bytes each
        Assert.True(scratch.Length >= 39, $"the scratch grew to {scratch.Length} characters");
    }

    [Fact]
    public void FlatDocumentBytes_AllocateOnlyTheirArray()
    {
        string[] attributes = ["R/@ID", "R/@V"];
        var values = new Dictionary<string, string>(StringComparer.Ordinal) { ["R/@ID"] = "12345" };
        char[] scratch = new char[64];
        EkiSendDocument.WriteFlatBytes("R", attributes, values, ref scratch); // compiled and warmed before the count

        long before = GC.GetAllocatedBytesForCurrentThread();
        byte[] bytes = EkiSendDocument.WriteFlatBytes("R", attributes, values, ref scratch);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.Equal("<R ID=\"12345\" />"u8.ToArray(), bytes);
        // A byte[16] is 40 bytes on a 64-bit runtime (header, method table, length, 16 bytes); the string a send made before was 56 more.
        Assert.Equal(40, allocated);
    }
}

using System.Buffers.Binary;
using System.Text;

namespace Machina.Tests.Online;

/// <summary>
/// The UR wire codecs and RTDE decoding at their edges, with exact bytes and values (the gaps mutation testing found): bytes
/// appended before earlier ones are read, a package larger than the 4,096-byte RTDE buffer, RTDE types beyond the driver's
/// recipe, the int32 limits of the driver protocol and the runtime exception packages of the script port.
/// </summary>
public class UrWireDecodingTests
{
    private static byte[] RtdePackage(byte type, int payloadLength, byte fill)
    {
        byte[] payload = Enumerable.Repeat(fill, payloadLength).ToArray();
        return Rtde.Package(type, payload);
    }

    [Fact]
    public void RtdePackage_BigEndianSizeWithHeader_TypeThenPayload()
    {
        Assert.Equal(new byte[] { 0, 6, (byte)'V', 0, 2, 9 }, Rtde.Package(Rtde.RequestProtocolVersion, [0, 2, 9]));
        Assert.Equal(new byte[] { 0, 3, (byte)'S' }, Rtde.Package(Rtde.Start, []));
        byte[] big = Rtde.Package(Rtde.DataPackage, new byte[300]);
        Assert.Equal((1, 47, (byte)'U', 303), (big[0], big[1], big[2], big.Length));
    }

    [Theory]
    [InlineData("VECTOR6D", 48)]
    [InlineData("VECTOR3D", 24)]
    [InlineData("VECTOR6INT32", 24)]
    [InlineData("VECTOR6UINT32", 24)]
    [InlineData("DOUBLE", 8)]
    [InlineData("UINT64", 8)]
    [InlineData("INT32", 4)]
    [InlineData("UINT32", 4)]
    [InlineData("UINT8", 1)]
    [InlineData("BOOL", 1)]
    [InlineData("NOT_FOUND", 0)]
    [InlineData("double", 0)]
    [InlineData("", 0)]
    public void RtdeSizeOf_EveryType_BeyondTheRecipeToo(string type, int bytes) => Assert.Equal(bytes, Rtde.SizeOf(type));

    [Fact]
    public void RtdeReader_BytesAppendedBeforeEarlierOnesAreRead_AllPackagesInOrder()
    {
        var reader = new RtdePackageReader();
        byte[] first = RtdePackage(Rtde.TextMessage, 5, 0x11);
        byte[] second = RtdePackage(Rtde.DataPackage, 7, 0x22);
        byte[] third = RtdePackage(Rtde.Pause, 1, 0x33);
        reader.Append(first);
        reader.Append(second.AsSpan(0, 4));
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.TextMessage, "11-11-11-11-11"), (type, BitConverter.ToString(payload.ToArray())));
        Assert.False(reader.TryRead(out type, out payload)); // 4 of second's 10 bytes
        Assert.Equal((0, 0), (type, payload.Length));
        reader.Append([.. second.AsSpan(4), .. third]);
        Assert.True(reader.TryRead(out type, out payload));
        Assert.Equal((Rtde.DataPackage, "22-22-22-22-22-22-22"), (type, BitConverter.ToString(payload.ToArray())));
        Assert.True(reader.TryRead(out type, out payload));
        Assert.Equal((Rtde.Pause, "33"), (type, BitConverter.ToString(payload.ToArray())));
        Assert.False(reader.TryRead(out _, out _));
    }

    [Fact]
    public void RtdeReader_HeaderInPieces_WaitsForAllThreeBytes()
    {
        var reader = new RtdePackageReader();
        byte[] package = RtdePackage(Rtde.Start, 1, 1);
        reader.Append(package.AsSpan(0, 1));
        Assert.False(reader.TryRead(out _, out _));
        reader.Append(package.AsSpan(1, 1));
        Assert.False(reader.TryRead(out _, out _));
        reader.Append(package.AsSpan(2, 1));
        Assert.False(reader.TryRead(out _, out _));
        reader.Append(package.AsSpan(3));
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.Start, 1, (byte)1), (type, payload.Length, payload[0]));
    }

    [Fact]
    public void RtdeReader_EmptyPayloadPackage_ReadWithItsType()
    {
        var reader = new RtdePackageReader();
        reader.Append([0, 3, Rtde.Pause, 0, 4, Rtde.Start, 1]);
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.Pause, 0), (type, payload.Length));
        Assert.True(reader.TryRead(out type, out payload));
        Assert.Equal((Rtde.Start, 1, (byte)1), (type, payload.Length, payload[0]));
    }

    [Fact]
    public void RtdeReader_LoneHeaderOnlyPackage_Read()
    {
        var reader = new RtdePackageReader();
        reader.Append([0, 3, Rtde.Pause]);
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.Pause, 0), (type, payload.Length));
        Assert.False(reader.TryRead(out _, out _));
    }

    [Theory]
    [InlineData(0)]
    [InlineData(1)]
    [InlineData(2)]
    public void RtdeReader_SizeShorterThanItsHeader_ConnectionError(int size)
    {
        var reader = new RtdePackageReader();
        reader.Append([0, (byte)size, Rtde.DataPackage, 9, 9]);
        RobotConnectionException e = Assert.Throws<RobotConnectionException>(() => reader.TryRead(out _, out _));
        Assert.Equal($"The controller sent an RTDE package of {size} bytes, shorter than its header.", e.Message);
    }

    [Fact]
    public void RtdeReader_PackagesFillingTheBufferRepeatedly_KeepsThePartlyReadTailAcrossTheMove()
    {
        // Packages of 1,000 bytes: the fifth append no longer fits behind what was read, so the unread tail moves to the front.
        var reader = new RtdePackageReader();
        var expected = new List<byte>();
        var read = new List<byte>();
        for (int i = 0; i < 12; i++)
        {
            byte[] package = RtdePackage(Rtde.DataPackage, 997, (byte)(i + 1));
            expected.Add((byte)(i + 1));
            // Each package arrives in two pieces, the second with the next package's start behind it.
            reader.Append(package.AsSpan(0, 600));
            while (reader.TryRead(out _, out ReadOnlySpan<byte> payload))
            {
                Assert.Equal(997, payload.Length);
                Assert.True(payload.IndexOfAnyExcept(payload[0]) < 0);
                read.Add(payload[0]);
            }
            reader.Append(package.AsSpan(600));
            while (reader.TryRead(out _, out ReadOnlySpan<byte> payload))
            {
                Assert.Equal(997, payload.Length);
                Assert.True(payload.IndexOfAnyExcept(payload[0]) < 0);
                read.Add(payload[0]);
            }
        }
        Assert.Equal(expected, read);
    }

    [Fact]
    public void RtdeReader_UnreadBytesPlusNewOnesBeyond4096_BufferGrowsAndKeepsEverything()
    {
        var reader = new RtdePackageReader();
        byte[] small = RtdePackage(Rtde.TextMessage, 97, 0x41); // 100 bytes
        byte[] large = RtdePackage(Rtde.DataPackage, 6_997, 0x5A); // 7,000 bytes, more than the initial 4,096
        reader.Append(small);
        reader.Append(large.AsSpan(0, 3_000)); // 3,100 unread bytes
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.TextMessage, 97), (type, payload.Length));
        Assert.False(reader.TryRead(out _, out _));
        reader.Append(large.AsSpan(3_000, 3_000)); // 6,000 unread: more than the buffer holds
        Assert.False(reader.TryRead(out _, out _));
        reader.Append([.. large.AsSpan(6_000), .. small]);
        Assert.True(reader.TryRead(out type, out payload));
        Assert.Equal((Rtde.DataPackage, 6_997), (type, payload.Length));
        Assert.True(payload.IndexOfAnyExcept((byte)0x5A) < 0);
        Assert.True(reader.TryRead(out type, out payload));
        Assert.Equal((Rtde.TextMessage, 97, -1), (type, payload.Length, payload.IndexOfAnyExcept((byte)0x41)));
        Assert.False(reader.TryRead(out _, out _));
    }

    [Fact]
    public void RtdeReader_OneAppendOfMoreThanTwiceTheBuffer_Read()
    {
        var reader = new RtdePackageReader();
        reader.Append(RtdePackage(Rtde.TextMessage, 10, 1));
        Assert.True(reader.TryRead(out _, out _));
        byte[] huge = RtdePackage(Rtde.DataPackage, 60_000, 0x7E);
        reader.Append(huge);
        Assert.True(reader.TryRead(out byte type, out ReadOnlySpan<byte> payload));
        Assert.Equal((Rtde.DataPackage, 60_000, -1), (type, payload.Length, payload.IndexOfAnyExcept((byte)0x7E)));
    }

    [Theory]
    [InlineData(0.0, 0)]
    [InlineData(1.0, 1_000)]
    [InlineData(-1.0, -1_000)]
    [InlineData(0.0005, 1)] // 0.5 wire units round away from zero
    [InlineData(-0.0005, -1)]
    [InlineData(0.0004, 0)]
    [InlineData(0.01, 10)]
    [InlineData(400.0, 400_000)]
    [InlineData(-123.4567, -123_457)]
    [InlineData(2_000_000.0, 2_000_000_000)] // 2 km: still within int32
    public void Millimetres_ThousandthsOfAMillimetre_RoundedAwayFromZero(double mm, int wire) => Assert.Equal(wire, UrWire.Millimetres(mm));

    [Fact]
    public void Degrees_MillionthsOfARadian()
    {
        Assert.Equal(1_570_796, UrWire.Degrees(90));
        Assert.Equal(-3_141_593, UrWire.Degrees(-180));
        Assert.Equal(0, UrWire.Degrees(0));
        Assert.Equal(175, UrWire.Degrees(0.01)); // 0.01° = 174.5 µrad: the wire carries a hundredth of a degree
        Assert.Equal(90.0, UrWire.ToDegrees(1_570_796), 4);
        Assert.Equal(-180.0, UrWire.ToDegrees(-3_141_593), 4);
        Assert.Equal(1_570_796 / 1_000_000.0 * 180 / Math.PI, UrWire.ToDegrees(1_570_796), 12);
        Assert.Equal(400.0, UrWire.ToMillimetres(400_000), 12);
        Assert.Equal(-0.001, UrWire.ToMillimetres(-1), 12);
    }

    [Fact]
    public void Wire_EveryReachableValue_FitsInt32_AndBeyondIsRefused()
    {
        // Any position or speed a robot reaches (a few metres, a few m/s) and any joint angle (±6,000°) fits with room to spare.
        Assert.Equal(-100_000_000, UrWire.Millimetres(-100_000));
        Assert.Equal(104_719_755, UrWire.Degrees(6_000));
        Assert.Equal(2_147_483_000, UrWire.Millimetres(2_147_483));
        Assert.Throws<ArgumentOutOfRangeException>(() => UrWire.Millimetres(2_147_484));
        Assert.Throws<ArgumentOutOfRangeException>(() => UrWire.Degrees(123_042));
    }

    [Theory]
    [InlineData(2.5, 3)]
    [InlineData(-2.5, -3)]
    [InlineData(2.4999, 2)]
    [InlineData(2147483646.0, 2147483646)]
    [InlineData(-2147483646.0, -2147483646)]
    public void Scale_RoundsToTheNearestInteger(double scaled, int wire) => Assert.Equal(wire, UrWire.Scale(scaled));

    [Theory]
    [InlineData(2147483647.0)]
    [InlineData(-2147483647.0)]
    [InlineData(1e300)]
    [InlineData(double.NaN)]
    [InlineData(double.PositiveInfinity)]
    [InlineData(double.NegativeInfinity)]
    public void Scale_BeyondInt32_Refused(double scaled)
    {
        ArgumentOutOfRangeException e = Assert.Throws<ArgumentOutOfRangeException>(() => UrWire.Scale(scaled));
        Assert.Equal("scaled", e.ParamName);
        Assert.Equal(scaled, e.ActualValue);
        Assert.StartsWith("The value is too large for the UR driver protocol (32-bit integers).", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Write_BigEndianInt32s_ReturnsTheBytesWritten()
    {
        var into = new byte[14];
        Array.Fill(into, (byte)0xEE);
        Assert.Equal(12, UrWire.Write([1, -2, int.MinValue], into));
        Assert.Equal("00-00-00-01-FF-FF-FF-FE-80-00-00-00-EE-EE", BitConverter.ToString(into));
        Assert.Equal(0, UrWire.Write([], into));
    }

    private static byte[] Ints(params int[] values)
    {
        var bytes = new byte[values.Length * 4];
        UrWire.Write(values, bytes);
        return bytes;
    }

    private static List<string> ReadAll(UrDriverReader reader)
    {
        var read = new List<string>();
        while (reader.TryRead(out UrReply reply))
        {
            read.Add(reply.Response is int[] r ? "[" + string.Join(',', r) + "]" : reply.Acknowledged.ToString(System.Globalization.CultureInfo.InvariantCulture));
        }
        return read;
    }

    [Fact]
    public void DriverReader_AcknowledgementsAndResponses_ZeroAndMinusOneMeanNothing()
    {
        var reader = new UrDriverReader();
        reader.Append(Ints(0, 5, -1, UrWire.ResponseVersion, 2, 0, -1, UrWire.End, 6, UrWire.ResponseInput, 6, 1_000_000, UrWire.End));
        Assert.Equal(["5", "[-50,2,0,-1]", "6", "[-60,6,1000000]"], ReadAll(reader));
        Assert.False(reader.TryRead(out UrReply none));
        Assert.Equal(new UrReply(0, null), none);
    }

    [Fact]
    public void DriverReader_BytesAppendedBeforeEarlierOnesAreRead_NothingLostOrRepeated()
    {
        var reader = new UrDriverReader();
        var expected = new List<string>();
        var read = new List<string>();
        for (int id = 1; id <= 200; id++)
        {
            // 1.5 values per append, two appends per read: unread bytes pile up and outgrow the 256-byte start.
            byte[] value = Ints(id);
            reader.Append(value.AsSpan(0, 2));
            reader.Append(value.AsSpan(2));
            expected.Add(id.ToString(System.Globalization.CultureInfo.InvariantCulture));
            if (id % 3 == 0 && reader.TryRead(out UrReply one))
            {
                read.Add(one.Acknowledged.ToString(System.Globalization.CultureInfo.InvariantCulture));
            }
        }
        read.AddRange(ReadAll(reader));
        Assert.Equal(expected, read);
    }

    [Fact]
    public void DriverReader_ResponseAcrossAppends_AfterPartReads()
    {
        var reader = new UrDriverReader();
        byte[] stream = Ints([7, UrWire.ResponseFullPose, .. Enumerable.Range(1, 12), UrWire.End, 8]);
        reader.Append(stream.AsSpan(0, 6));
        Assert.Equal(["7"], ReadAll(reader));
        reader.Append(stream.AsSpan(6, 30));
        Assert.Empty(ReadAll(reader));
        reader.Append(stream.AsSpan(36));
        Assert.Equal(["[-54,1,2,3,4,5,6,7,8,9,10,11,12]", "8"], ReadAll(reader));
    }

    [Fact]
    public void DriverReader_OneLargeAppend_LargerThanTwiceTheStart()
    {
        var reader = new UrDriverReader();
        reader.Append(Ints(1));
        reader.Append(Ints([.. Enumerable.Range(2, 299)]));
        Assert.Equal(Enumerable.Range(1, 300).Select(i => i.ToString(System.Globalization.CultureInfo.InvariantCulture)), ReadAll(reader));
    }

    [Fact]
    public void DriverReader_ResponseOfExactly64Values_Accepted_65Refused()
    {
        var reader = new UrDriverReader();
        reader.Append(Ints([UrWire.ResponseFullPose, .. Enumerable.Range(1, 63), UrWire.End]));
        Assert.True(reader.TryRead(out UrReply reply));
        Assert.Equal(64, reply.Response!.Length);
        reader.Append(Ints([UrWire.ResponseFullPose, .. Enumerable.Range(1, 64), UrWire.End]));
        RobotConnectionException e = Assert.Throws<RobotConnectionException>(() => reader.TryRead(out _));
        Assert.Equal("The UR driver sent a response longer than 64 values that never ends; is it Machina's driver?", e.Message);
    }

    [Fact]
    public void RuntimeException_Package_ExactBytes()
    {
        byte[] package = UrRobotMessage.RuntimeException(0x0102030405060708, 99, 7, "ab");
        Assert.Equal("00-00-00-19-14-01-02-03-04-05-06-07-08-FE-0A-00-00-00-63-00-00-00-07-61-62", BitConverter.ToString(package));
    }

    private static (List<string> Texts, UrRobotMessage.Reader Reader) Reader()
    {
        var texts = new List<string>();
        return (texts, new UrRobotMessage.Reader(texts.Add));
    }

    [Fact]
    public void RobotMessageReader_OneByteAtATime_TextWithItsLine_OrWithoutALine()
    {
        (List<string> texts, UrRobotMessage.Reader reader) = Reader();
        byte[] stream = [.. UrRobotMessage.RuntimeException(1, 12, 3, "name 'x' is not defined"), .. UrRobotMessage.RuntimeException(2, 0, 0, "stopped")];
        foreach (byte b in stream)
        {
            reader.OnReceived([b]);
        }
        reader.OnClosed(null);
        Assert.Equal(["name 'x' is not defined (driver script line 12)", "stopped"], texts);
    }

    [Fact]
    public void RobotMessageReader_OtherPackagesSkipped()
    {
        (List<string> texts, UrRobotMessage.Reader reader) = Reader();
        byte[] otherType = UrRobotMessage.RuntimeException(1, 5, 0, "other");
        otherType[4] = 16; // robot state
        byte[] otherMessage = UrRobotMessage.RuntimeException(1, 5, 0, "popup");
        otherMessage[14] = 2;
        byte[] shortOne = [0, 0, 0, 15, UrRobotMessage.RobotMessage, 0, 0, 0, 0, 0, 0, 0, 0, 0xFE, UrRobotMessage.RuntimeExceptionType];
        byte[] minimal = [0, 0, 0, 5, 99];
        reader.OnReceived([.. otherType, .. otherMessage, .. shortOne, .. minimal, .. UrRobotMessage.RuntimeException(1, -1, 0, "")]);
        reader.OnReceived(UrRobotMessage.RuntimeException(1, 1, 0, "last"));
        Assert.Equal(["", "last (driver script line 1)"], texts);
    }

    [Theory]
    [InlineData(4)]
    [InlineData(0)]
    [InlineData(-1)]
    [InlineData(UrRobotMessage.MaxPackage + 1)]
    public void RobotMessageReader_SizeNoControllerSends_StopsReadingForGood(int size)
    {
        (List<string> texts, UrRobotMessage.Reader reader) = Reader();
        byte[] bad = new byte[5];
        BinaryPrimitives.WriteInt32BigEndian(bad, size);
        reader.OnReceived([.. bad, .. UrRobotMessage.RuntimeException(1, 1, 0, "hidden")]);
        reader.OnReceived(UrRobotMessage.RuntimeException(1, 1, 0, "hidden too"));
        Assert.Empty(texts);
    }

    [Fact]
    public void RobotMessageReader_PackageOfTheLargestSize_Read()
    {
        (List<string> texts, UrRobotMessage.Reader reader) = Reader();
        string text = new('x', UrRobotMessage.MaxPackage - 23);
        byte[] largest = UrRobotMessage.RuntimeException(1, 2, 0, text);
        Assert.Equal(UrRobotMessage.MaxPackage, largest.Length);
        reader.OnReceived(largest.AsSpan(0, 4));
        Assert.Empty(texts); // fewer than 5 bytes: not even the size is judged
        reader.OnReceived(largest.AsSpan(4));
        reader.OnReceived(UrRobotMessage.RuntimeException(1, 3, 0, "next"));
        Assert.Equal(2, texts.Count);
        Assert.Equal(text + " (driver script line 2)", texts[0]);
        Assert.Equal("next (driver script line 3)", texts[1]);
    }

    private static byte[] Sample(double value = 0, int robotMode = 7, int safety = 1, uint runtime = 2)
    {
        var payload = new byte[UrDriver.PackageLength];
        payload[0] = 1;
        BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(1), 12.5); // timestamp, not read
        for (int i = 0; i < 6; i++)
        {
            BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(9 + i * 8), (i + 1) * 0.1);
            BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(57 + i * 8), i < 3 ? (i + 1) * 0.1 : 0);
        }
        BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(57), value);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(105), robotMode);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(109), safety);
        BinaryPrimitives.WriteUInt32BigEndian(payload.AsSpan(113), runtime);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(117), 41);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(121), 42);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(125), 43);
        return payload;
    }

    [Fact]
    public void Decode_EveryField_InItsPlace()
    {
        RtdeSample sample = UrDriver.Decode(Sample(0.25, robotMode: 7, safety: 3, runtime: 0xFFFFFFFF));
        Assert.Equal(250, sample.Position.X, 9);
        Assert.Equal(200, sample.Position.Y, 9);
        Assert.Equal(300, sample.Position.Z, 9);
        double[] joints = [sample.Joints.J1, sample.Joints.J2, sample.Joints.J3, sample.Joints.J4, sample.Joints.J5, sample.Joints.J6];
        for (int i = 0; i < 6; i++)
        {
            Assert.Equal((i + 1) * 0.1 * 180 / Math.PI, joints[i], 9);
        }
        Assert.Equal((7, 3, 0xFFFFFFFFu, 41, 42, 43), (sample.RobotMode, sample.SafetyStatus, sample.RuntimeState, sample.Executed, sample.Received, sample.Instance));
    }

    [Fact]
    public void Decode_RotationVector_DegreesFromRadians()
    {
        byte[] payload = Sample(0.4);
        BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(57 + 5 * 8), Math.PI / 2); // 90° about Z
        RtdeSample sample = UrDriver.Decode(payload);
        Vector x = sample.Rotation.Rotate(new Vector(1, 0, 0));
        Assert.Equal(0, x.X, 9);
        Assert.Equal(1, x.Y, 9);
    }

    [Theory]
    [InlineData(1000.0)] // 1e6 mm: the largest plausible value
    [InlineData(-1000.0)]
    public void Decode_LargestPlausibleValue_Accepted(double metres) => Assert.Equal(metres * 1000, UrDriver.Decode(Sample(metres)).Position.X, 6);

    [Theory]
    [InlineData(1000.001, "1000001")]
    [InlineData(-1000.001, "-1000001")]
    public void Decode_BeyondThePlausible_CorruptWithTheField(double metres, string shown)
    {
        RobotConnectionException e = Assert.Throws<RobotConnectionException>(() => UrDriver.Decode(Sample(metres)));
        Assert.StartsWith($"The UR controller sent {shown}", e.Message, StringComparison.Ordinal);
        Assert.EndsWith(" in actual_TCP_pose of an RTDE data package: no arm reports that; the data is corrupt.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Decode_CorruptJoint_NamesActualQ()
    {
        byte[] payload = Sample();
        BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(9 + 40), double.NaN);
        RobotConnectionException e = Assert.Throws<RobotConnectionException>(() => UrDriver.Decode(payload));
        Assert.Equal("The UR controller sent NaN in actual_q of an RTDE data package: no arm reports that; the data is corrupt.", e.Message);
    }

    [Theory]
    [InlineData(128)]
    [InlineData(130)]
    [InlineData(0)]
    public void Decode_WrongLength_ConnectionError(int length)
    {
        RobotConnectionException e = Assert.Throws<RobotConnectionException>(() => UrDriver.Decode(new byte[length]));
        Assert.Equal($"The UR controller sent an RTDE data package of {length} bytes; the recipe has 129.", e.Message);
    }

    [Fact]
    public void RuntimeException_AsciiText() => Assert.Equal("ab", Encoding.ASCII.GetString(UrRobotMessage.RuntimeException(0, 0, 0, "ab").AsSpan(23)));
}

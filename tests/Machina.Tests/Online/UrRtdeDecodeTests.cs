using System.Buffers.Binary;

namespace Machina.Tests.Online;

public class UrRtdeDecodeTests
{
    /// <summary>A data package of the driver's recipe: q in radians, the TCP pose in metres and a rotation vector.</summary>
    private static byte[] Package(double[] q, double[] tcp)
    {
        var payload = new byte[UrDriver.PackageLength];
        payload[0] = 1;
        for (int i = 0; i < 6; i++)
        {
            BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(9 + i * 8), q[i]);
            BinaryPrimitives.WriteDoubleBigEndian(payload.AsSpan(57 + i * 8), tcp[i]);
        }
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(105 + 12), 7);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(105 + 16), 9);
        BinaryPrimitives.WriteInt32BigEndian(payload.AsSpan(105 + 20), 123_456_789);
        return payload;
    }

    [Fact]
    public void Decode_ValidSample_MillimetresDegreesAndIds()
    {
        var sample = UrDriver.Decode(Package([0, -Math.PI / 2, 0, 0, Math.PI / 2, 0], [0.4, -0.1, 0.5, 0, 0, 0]));
        Assert.Equal(new Vector(400, -100, 500), sample.Position);
        Assert.Equal(-90, sample.Joints.J2, 9);
        Assert.Equal((7, 9, 123_456_789), (sample.Executed, sample.Received, sample.Instance));
        Assert.Equal(129, UrDriver.PackageLength);
    }

    [Theory]
    [InlineData(double.NaN, 0)]
    [InlineData(0, double.PositiveInfinity)]
    [InlineData(1e300, 0)]
    [InlineData(0, 1e300)]
    [InlineData(0, -2e4)]
    public void Decode_CorruptNumber_ConnectionErrorNotArgumentException(double joint, double rotationVector)
    {
        var payload = Package([joint, 0, 0, 0, 0, 0], [0.4, 0, 0.5, rotationVector, 0, 0]);
        var e = Assert.Throws<RobotConnectionException>(() => UrDriver.Decode(payload));
        Assert.Contains("corrupt", e.Message, StringComparison.Ordinal);
    }
}

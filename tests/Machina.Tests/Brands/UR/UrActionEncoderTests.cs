using System.Buffers.Binary;

namespace Machina.Tests.Brands.UR;

public class UrActionEncoderTests
{
    private readonly RobotCursor _cursor = new();
    private int _nextId = 1;

    /// <summary>Applies the action to the cursor with the next id and returns the integers it is sent as.</summary>
    private int[] Wire(RobotAction action)
    {
        action.Id = _nextId++;
        Assert.Null(_cursor.TryApply(action));
        var values = new int[UrActionEncoder.MaxValues];
        return values[..UrActionEncoder.Encode(action, _cursor, values)];
    }

    [Fact]
    public void Encode_MotionActions_ExactIntegers()
    {
        // Tool down: quaternion (0, 0, 1, 0) is the rotation vector (0, π, 0) rad = (0, 3141593, 0) in 1e-6 rad.
        Assert.Equal([1, 1, 400_000, 0, 500_000, 0, 3_141_593, 0], Wire(new ActionTransformation(new Vector(400, 0, 500), Rotation.FromQuaternion(0, 0, 1, 0), false, true)));
        Assert.Equal([2, 1, 450_500, 0, 500_000, 0, 3_141_593, 0], Wire(new ActionTranslation(new Vector(50.5, 0, 0), true)));
        Wire(new ActionMotionMode(MotionType.Joint));
        Assert.Equal([4, 2, 450_500, 0, 450_000, 0, 3_141_593, 0], Wire(new ActionTranslation(new Vector(0, 0, -50), true)));
        Assert.Equal([5, 3, 0, -1_570_796, 0, 0, 1_570_796, 0], Wire(new ActionAxes(new Joints(0, -90, 0, 0, 90, 0), false)));
    }

    [Fact]
    public void Encode_Settings_ExactIntegers()
    {
        Assert.Equal([1, 15, 100_000], Wire(new ActionSpeed(100, false)));
        Assert.Equal([2, 16, 500_000], Wire(new ActionAcceleration(500, false)));
        Assert.Equal([3, 8, 2_000], Wire(new ActionPrecision(2, false)));
        Assert.Equal([4, 9, 1500], Wire(new ActionWait(1500)));
        Assert.Empty(Wire(new ActionMessage("Hello world!")));
        Assert.Equal([6, 13, 7, 1, 0], Wire(new ActionIODigital("7", true, false)));
        Assert.Equal([7, 13, 1, 0, 1], Wire(new ActionIODigital("1", false, true)));
        Assert.Equal([8, 14, 1, 500_000], Wire(new ActionIOAnalog("1", 0.5, false)));
    }

    [Fact]
    public void Encode_PushPop_OnlyChangedSettingsAndTheIdOnTheLast()
    {
        Wire(new ActionPushPop(true));
        Wire(new ActionSpeed(50, false));
        Wire(new ActionPrecision(3, false));
        Assert.Equal([0, 15, 20_000, 4, 8, 5_000], Wire(new ActionPushPop(false)));
        Wire(new ActionPushPop(true));
        Assert.Empty(Wire(new ActionPushPop(false)));
    }

    [Fact]
    public void Write_BigEndian()
    {
        var bytes = new byte[8];
        Assert.Equal(8, UrWire.Write([1, int.MinValue], bytes));
        Assert.Equal([0, 0, 0, 1, 0x80, 0, 0, 0], bytes);
        Assert.Equal(-54, BinaryPrimitives.ReadInt32BigEndian(new byte[] { 0xFF, 0xFF, 0xFF, 0xCA }));
    }

    [Theory]
    [InlineData(30003, 30004, 29999)]
    [InlineData(30001, 30004, 29999)]
    [InlineData(41000, 41001, 41002)]
    public void Ports_FromTheScriptPort(int script, int rtde, int dashboard) =>
        Assert.Equal(new UrPorts(script, rtde, dashboard), UrPorts.For(script));

    [Fact]
    public void DriverModules_HostAndPort_FilledInTheScript()
    {
        var bot = Robot.Create("U", "UR");
        var files = bot.GetDeviceDriverModules(new Dictionary<string, string> { ["HOSTNAME"] = "192.168.0.5", ["PORT"] = "50123" });
        string script = Assert.Single(files).Value;
        Assert.Equal("machina_ur_driver.script", files.Keys.Single());
        Assert.Contains("  HOSTNAME = \"192.168.0.5\"\n  PORT = 50123\n", script, StringComparison.Ordinal);
        Assert.Contains("  INSTANCE = 1\n", script, StringComparison.Ordinal);
        Assert.Contains("  VALUES_TIMEOUT = 5.0\n", script, StringComparison.Ordinal);
        Assert.DoesNotContain("{{", script, StringComparison.Ordinal);
        // The script manual's shape: def in column 1 first, every other line indented, end in column 1 last, no call line.
        Assert.StartsWith("def machina_ur_driver():\n", script, StringComparison.Ordinal);
        Assert.EndsWith("\nend\n", script, StringComparison.Ordinal);
        Assert.Equal(["def machina_ur_driver():", "end"], script.Split('\n').Where(l => l.Length > 0 && !char.IsWhiteSpace(l[0])).ToArray());
    }

    [Fact]
    public void DriverScript_ValuesTimeout_FilledInSecondsAndNeverZero()
    {
        string script = UrDriverScript.For("127.0.0.1", 7000, 3, TimeSpan.FromMilliseconds(250));
        Assert.Contains("  VALUES_TIMEOUT = 0.25\n", script, StringComparison.Ordinal);
        Assert.Contains("socket_read_binary_integer(n, SOCKET, VALUES_TIMEOUT)", script, StringComparison.Ordinal);
        // 0 would never time out on a UR (script manual): a stalled stream would hold the program for ever.
        Assert.Throws<ArgumentOutOfRangeException>(() => UrDriverScript.For("127.0.0.1", 7000, 3, TimeSpan.Zero));
        Assert.Throws<ArgumentOutOfRangeException>(() => UrDriverScript.For("127.0.0.1", 7000, 0));
    }
}

using System.Buffers.Binary;
using Machina.Simulation;
using Machina.Simulation.UrScript;
using static Machina.Tests.Online.ArcOnlineSupport;
using static Machina.Tests.Online.OnlineTestSupport;
using static Machina.Tests.Online.UrOnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// Arcs online on UR (issue 46): the driver's <c>movec</c> instruction (code 21) carries the via pose and the target the URScript
/// compiler writes, and an arc streamed to the twin ends where the compiled program ends on the same twin.
/// </summary>
public class UrArcOnlineTests
{
    /// <summary>From a joint position, a joint move to a pose with the tool down, a straight move, then the arc of square.machina.</summary>
    private const string Program = """
        SpeedTo(100);
        AxesTo(0, -90, 90, -90, -90, 0);
        MotionMode("joint");
        TransformTo(300, -100, 400, -1, 0, 0, 0, 1, 0);
        MotionMode("linear");
        Move(0, 0, -100);
        ArcMotionTo(375, 0, 360, 300, 100, 300);
        Wait(100);
        """;

    [Fact]
    public void Encode_ArcMotion_ViaPoseThenTarget_ExactIntegersAndBytes()
    {
        var cursor = new RobotCursor();
        RobotAction start = new ActionTransformation(new Vector(300, -100, 300), Rotation.FromQuaternion(0, 0, 1, 0), false, true) { Id = 1 };
        Assert.Null(cursor.TryApply(start));
        RobotAction arc = Instructions.Parse("ArcMotionTo(375, 0, 360.1, 300, 100, 300);")[0];
        arc.Id = 2;
        Assert.Null(cursor.TryApply(arc));

        var values = new int[UrActionEncoder.MaxValues];
        int count = UrActionEncoder.Encode(arc, cursor, values);

        // Tool down: the rotation vector (0, π, 0) rad = (0, 3141593, 0) in 1e-6 rad, at the via point and at the target.
        int[] expected = [2, 21, 375_000, 0, 360_100, 0, 3_141_593, 0, 300_000, 100_000, 300_000, 0, 3_141_593, 0];
        Assert.Equal(expected, values[..count]);
        var bytes = new byte[count * 4];
        Assert.Equal(56, UrWire.Write(values.AsSpan(0, count), bytes));
        Assert.Equal([0, 0, 0, 2, 0, 0, 0, 21, 0, 0x05, 0xB8, 0xD8], bytes[..12]);
        Assert.Equal(360_100, BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(16)));
        Assert.Equal(3_141_593, BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(48)));
        Assert.Null(new UrOnline().WhyCannotStream(arc));
    }

    [Fact]
    public void DriverScript_RunsCode21AsTheCompilersMovec()
    {
        string script = UrDriverScript.For("127.0.0.1", 7000);
        Assert.Contains("  INST_MOVEC = 21\n", script, StringComparison.Ordinal);
        Assert.Contains("movec(pose_of(c), second_pose_of(c), a=acceleration, v=speed, r=blend, mode=0)", script, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Stream_Arc_EndsWhereTheCompiledProgramEndsOnTheTwin()
    {
        RobotModel model = RobotModels.Get("UR5e");
        string script = Assert.Single(Compile(RobotType.UR, Program, model)).Text;
        Assert.Contains("movec(p[0.375,0,0.36,0,3.141593,0], p[0.3,0.1,0.3,0,3.141593,0], v=0.1, r=0.005)", script, StringComparison.Ordinal);
        using var offline = new UrTwinController(new UrTwinOptions { Model = model });
        Assert.Equal(UrProgramState.Finished, offline.Run(script, CancellationToken.None));

        await using var controller = await StartUrAsync(new VirtualUrControllerOptions { InstantExecution = true });
        Robot bot = await ConnectUrAsync(controller);
        try
        {
            IssueAll(bot, Program);
            await bot.WaitForCompletionAsync().WaitAsync(Limit);

            Assert.Empty(controller.Errors);
            Assert.Contains(controller.Twin.Arm.Trace, t => t.Text.StartsWith("movec", StringComparison.Ordinal));
            AssertSameEnd(offline.Arm, controller.Twin.Arm);
            Assert.True(controller.Twin.Arm.Tcp.Position.IsSimilar(new Vector(300, 100, 300), 0.01), controller.Twin.Arm.Tcp.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

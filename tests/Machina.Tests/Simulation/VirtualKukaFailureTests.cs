using System.Collections.Concurrent;
using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Simulation;

/// <summary>
/// "Executed" means the robot got there (issue 21 §1), KUKA: an action the driver's checks refuse is never acknowledged; the
/// driver sends <c>&lt;F ID Code Text&gt;</c> instead and halts, and nothing after it runs.
/// </summary>
public class VirtualKukaFailureTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    [Theory]
    [InlineData("3", "0 -90 90 0 170 0", KukaFailure.SoftwareLimit, "Software limit switch: an axis target is beyond its software limits.")]
    [InlineData("1", "2000 0 300 0 90 0", KukaFailure.NotReachable, "Target not reachable: no axis position within the software limit switches reaches it.")]
    [InlineData("4", "0 0 0 0 0 0", KukaFailure.NoSpeed, "The speed ($VEL.CP) is 0: the motion would never end.")]
    [InlineData("11", "5000 1 0 0 0 0", KukaFailure.NoSuchOutput, "Output does not exist: the number is outside the controller's outputs.")]
    [InlineData("12", "33 0.5 0 0 0 0", KukaFailure.NoSuchOutput, "Output does not exist: the number is outside the controller's outputs.")]
    [InlineData("12", "2 1.5 0 0 0 0", KukaFailure.AnalogRange, "Analog value out of range: $ANOUT takes values from -1 to 1.")]
    public async Task ActionTheRobotCannotRun_MidBatch_FailureInsteadOfAcknowledgementNothingAfterRuns(string type, string values, int code, string text)
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using var client = await KukaTestSupport.ConnectRawAsync(controller.Port);
        var reader = new KukaXmlReader();
        await KukaTestSupport.ReadElementAsync(client, reader);

        string batch = "<DT><DR>" + Action(1, "3", "0 -80 90 0 90 0") + Action(2, type, values) + Action(3, "3", "0 -90 90 0 90 0") + "</DR></DT>";
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(batch));
        KukaElement first = await KukaTestSupport.ReadElementAsync(client, reader);
        KukaElement second = await KukaTestSupport.ReadElementAsync(client, reader);

        Assert.Equal("<R ID=\"1\"></R>", first.ToString().Replace("/>", "></R>", StringComparison.Ordinal));
        Assert.Equal((KukaProtocol.Failure, 2, code.ToString(Num.Inv), text), (second.Name, second.Integer("ID"), second.Attribute("Code"), second.Attribute("Text")));
        Assert.Equal([1], controller.ExecutedIds);
        Assert.Equal(new Joints(0, -80, 90, 0, 90, 0), controller.State.Joints);
        // The driver's quit message (module, number, text of at most 80 characters), shown after it sent the failure.
        string quit = "QUIT Machina 2: " + text[..Math.Min(80, text.Length)];
        await Machina.Tests.Support.Eventually.TrueAsync(() => controller.PendantMessages.Contains(quit) && controller.Errors.Count > 0, "the quit message and the error", Timeout);
        Assert.Equal("refused: " + text, Assert.Single(controller.Errors));
        await controller.StopAsync();
        Assert.Equal([1], controller.ExecutedIds);
        Assert.Equal(1, controller.AcknowledgementsSent);
    }

    [Fact]
    public async Task DriverHalted_SaysSoOnThePendant_AndTheNextConnectionIsRefused()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        using (var client = await KukaTestSupport.ConnectRawAsync(controller.Port))
        {
            var reader = new KukaXmlReader();
            await KukaTestSupport.ReadElementAsync(client, reader);
            await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes("<DT><DR>" + Action(1, "3", "0 -90 90 0 170 0") + "</DR></DT>"));
            Assert.Equal(KukaProtocol.Failure, (await KukaTestSupport.ReadElementAsync(client, reader)).Name);
        }
        const string Ended = "machina_kuka_driver ended (stopped): the driver port no longer accepts connections; restart the virtual controller to serve again (on a KR C4: reset and start the program)";
        await Machina.Tests.Support.Eventually.TrueAsync(() => controller.PendantMessages.Contains(Ended), "the driver's end on the pendant", Timeout);

        // A driver that halted never opens its channel again: a host is refused at once, not left waiting for a state.
        using var late = new TcpClient();
        var refused = await Assert.ThrowsAsync<SocketException>(() => late.ConnectAsync(IPAddress.Loopback, controller.Port));
        Assert.Equal(SocketError.ConnectionRefused, refused.SocketErrorCode);
    }

    [Fact]
    public async Task HostDriver_DecodesFailure_ListenerGetsIdReasonAndCode()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync();
        var listener = new FailureRecordingListener();
        await using var host = new KukaDriver(new DeviceContext(new RobotLogger("test"), TimeProvider.System, "test", null, 50));
        await host.ConnectAsync("127.0.0.1", controller.Port, listener, Timeout, CancellationToken.None);
        var cursor = new RobotCursor();
        RobotAction[] program =
        [
            new ActionAxes(new Joints(0, -80, 90, 0, 90, 0), relative: false), new ActionAxes(new Joints(0, -90, 90, 0, 170, 0), relative: false),
            new ActionAxes(new Joints(0, -90, 90, 0, 90, 0), relative: false),
        ];
        for (int i = 0; i < program.Length; i++)
        {
            program[i].Id = i + 1;
            Assert.Null(cursor.TryApply(program[i]));
            Assert.True(host.Send(program[i], cursor));
        }

        var (id, reason, code) = await listener.Failed.Task.WaitAsync(Timeout);

        Assert.Equal((2, KukaFailure.Describe(KukaFailure.SoftwareLimit), "2"), (id, reason, code));
        Assert.Equal([1], listener.Acknowledged);
        Assert.Equal([1], controller.ExecutedIds);
        Assert.Empty(listener.Faults);
    }

    [Fact]
    public void FailureMessage_ReadBack_IdCodeText()
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes(KukaFailure.Message(12, KukaFailure.NoSpeed)));
        Assert.True(reader.TryRead(out KukaElement element));
        Assert.Equal("<F ID=\"12\" Code=\"3\" Text=\"The speed ($VEL.CP) is 0: the motion would never end.\"></F>", KukaFailure.Message(12, KukaFailure.NoSpeed));
        Assert.Equal(("F", 12, "3"), (element.Name, element.Integer("ID"), element.Attribute("Code")));
    }

    private static string Action(int id, string type, string values)
    {
        string[] v = values.Split(' ');
        var sb = new StringBuilder($"<A ID=\"{id}\" T=\"{type}\"");
        for (int i = 0; i < 7; i++)
        {
            sb.Append(Num.Inv, $" V{i + 1}=\"{(i < v.Length ? v[i] : "0")}\"");
        }
        return sb.Append(" M=\"\"/>").ToString();
    }
}

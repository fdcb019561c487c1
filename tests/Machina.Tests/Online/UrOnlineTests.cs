using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Support;
using static Machina.Tests.Online.OnlineTestSupport;
using static Machina.Tests.Online.UrOnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>Machina's URScript driver protocol end to end against the virtual UR: script, callback, instructions, acknowledgements.</summary>
public class UrOnlineTests
{
    private static readonly RobotModel Ur5e = RobotModels.Get("UR5e");

    [Fact]
    public async Task HelloRobot_Online_SevenOfSevenInOrderAndEndsAtTheRightPose()
    {
        await using var controller = await StartUrAsync(new VirtualUrControllerOptions { SpeedFactor = 50 });
        Robot bot = await ConnectUrAsync(controller);
        var released = new ConcurrentQueue<int>();
        var executed = new ConcurrentQueue<ActionExecutedArgs>();
        bot.ActionReleased += (_, e) => released.Enqueue(e.LastAction.Id);
        bot.ActionExecuted += (_, e) => executed.Enqueue(e);
        Pose start = Ur5e.Kinematics.Forward(new Joints(0, -90, -90, -90, 90, 0));
        Assert.True(bot.GetExecutedState().Position!.Value.IsSimilar(start.Position, 1e-6));

        ReferencePrograms.HelloRobot(bot);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);
        await bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Equal([1, 2, 3, 4, 5, 6, 7], released);
        Assert.Equal([1, 2, 3, 4, 5, 6, 7], executed.Select(e => e.LastAction.Id));
        // Message has nothing to run on a UR: it completes in order without being sent.
        Assert.Equal(["2 15 100000", "3 1 400000 300000 500000"], controller.ReceivedRequests.Take(2).Select(r => string.Join(' ', r.Split(' ').Take(5))));
        Assert.Equal("6 9 2000", controller.ReceivedRequests[4]);
        Assert.Equal("7 3 0 0 0 0 1570796 0", controller.ReceivedRequests[5]);
        Assert.Equal(6, controller.RequestsReceived);
        Assert.Empty(controller.Errors);
        var end = controller.State;
        // The wire carries 1e-6 rad: 90° arrives as 1.570796 rad = 89.99998°.
        Assert.True(end.Joints.IsSimilar(new Joints(0, 0, 0, 0, 90, 0), 0.001), end.Joints.ToString());
        Assert.True(end.Pose.IsSimilar(Ur5e.Kinematics.Forward(end.Joints), 1e-6, 1e-6));
        // The speed (100 mm/s) is the driver's own variable on the robot: its request, "2 15 100000", is checked above.
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), bot.GetExecutedState().Axes);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Stream_TenThousandActions_EachRunOnceInOrder()
    {
        await using var controller = await StartUrAsync();
        Robot bot = await ConnectUrAsync(controller, b => { b.BlockSize = 100; b.PendingCount = 100; });
        var executed = new ConcurrentQueue<int>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        bot.MoveTo(300, -300, 400);
        for (int i = 1; i < 10_000; i++)
        {
            bot.Move(i % 2 == 0 ? 10 : -10, 0, 0);
        }
        // The virtual UR interprets the driver script (about 2,500 actions/s alone, far fewer beside the rest of the suite):
        // the bound is generous because this test is about order and exactly once; speed is the benchmark's.
        await bot.WaitForCompletionAsync().WaitAsync(TimeSpan.FromMinutes(3));
        await bot.FlushEventsAsync().WaitAsync(TimeSpan.FromMinutes(1));

        Assert.Equal(Enumerable.Range(1, 10_000), executed);
        Assert.Equal(10_000, controller.RequestsExecuted);
        Assert.Equal(Enumerable.Range(1, 10_000), controller.ReceivedRequests.Select(r => int.Parse(r[..r.IndexOf(' ')], Num.Inv)));
        Assert.True(controller.State.Position.IsSimilar(new Vector(290, -300, 400), 1e-6), controller.State.Position.ToString());
        Assert.Empty(controller.Errors);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task Connect_Script_SentOnceWithTheLoopbackCallbackAndAnOsChosenPort()
    {
        await using var controller = await StartUrAsync();
        Robot bot = await ConnectUrAsync(controller);
        bot.Move(0, 0, 10);
        bot.Move(0, 0, 10);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Equal(1, controller.ScriptsReceived);
        string script = controller.LastScript!;
        Assert.Contains("HOSTNAME = \"127.0.0.1\"", script, StringComparison.Ordinal);
        Assert.DoesNotContain("PORT = 7003", script, StringComparison.Ordinal);
        Assert.DoesNotContain("{{", script, StringComparison.Ordinal);
        await bot.DisconnectAsync();
    }

    [Fact]
    public async Task TwoRobots_OneProcess_EachOwnCallbackPortAndNoInterference()
    {
        await using var first = await StartUrAsync();
        await using var second = await StartUrAsync();
        Robot a = await ConnectUrAsync(first, name: "A");
        Robot b = await ConnectUrAsync(second, name: "B");
        for (int i = 0; i < 100; i++)
        {
            a.Move(0, 0, -1);
            b.Move(0, 0, 1);
        }
        await Task.WhenAll(a.WaitForCompletionAsync(), b.WaitForCompletionAsync()).WaitAsync(Limit);

        Assert.Equal((100, 100), (first.RequestsExecuted, second.RequestsExecuted));
        Assert.NotEqual(CallbackPort(first.LastScript!), CallbackPort(second.LastScript!));
        Assert.Equal(first.State.Position.Z + 200, second.State.Position.Z, 6);
        await a.DisconnectAsync();
        await b.DisconnectAsync();
    }

    private static string CallbackPort(string script) => script.Split('\n').Single(l => l.TrimStart().StartsWith("PORT = ", StringComparison.Ordinal));

    [Fact]
    public async Task Issue_ActionTheDriverCannotRun_RefusedNamingIt()
    {
        await using var controller = await StartUrAsync();
        Robot bot = await ConnectUrAsync(controller);
        var e = Assert.Throws<ActionRefusedException>(() => bot.CustomCode("textmsg(\"hi\")"));
        Assert.Contains("cannot be streamed to a UR robot", e.Message, StringComparison.Ordinal);
        Assert.Throws<ActionRefusedException>(() => bot.WriteDigital("DO_A", true));
        await bot.DisconnectAsync();
    }
}

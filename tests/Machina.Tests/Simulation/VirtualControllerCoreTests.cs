using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The brand-neutral core of the virtual controllers, seen through the ABB front end: the robot model keeps joints and
/// pose consistent; a move the simulated robot cannot make stops the ABB driver (nothing more runs), and any other instruction it
/// cannot execute is refused, logged, acknowledged and survived.
/// </summary>
public class VirtualControllerCoreTests
{
    private static readonly RobotModel Irb120 = RobotModels.Get("IRB 120");

    [Fact]
    public async Task Start_DefaultAbb_IsAnIrb120AtHomeWhereItsKinematicsPutIt()
    {
        await using var controller = new VirtualAbbController();
        var s = controller.State;
        Assert.Equal("IRB 120", controller.Model!.Name);
        Assert.Equal(new Joints(0, 0, 0, 0, 90, 0), s.Joints);
        Assert.True(s.Position.IsSimilar(new Vector(302, 0, 558), 1e-9), s.Position.ToString());
        Assert.True(s.Rotation.IsSimilar(Rotation.FromQuaternion(0, 0, 1, 0), 1e-9), s.Rotation.ToString());
    }

    [Fact]
    public async Task Start_InitialPoseWithModel_JointsSolvedClosestToInitialJoints()
    {
        var pose = new Pose(new Vector(350, 50, 400), Rotation.FromQuaternion(0, 0, 1, 0));
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InitialPosition = pose.Position, InitialRotation = pose.Rotation });
        Assert.True(Irb120.Kinematics.Forward(controller.State.Joints).IsSimilar(pose, 1e-6, 1e-6));
    }

    [Fact]
    public void Start_UnreachableInitialPose_Throws()
    {
        var e = Assert.Throws<ArgumentException>(() => new VirtualAbbController(new VirtualAbbControllerOptions { InitialPosition = new Vector(2000, 0, 0) }));
        Assert.Contains("cannot reach the initial pose", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Moves_WithModel_JointsAndPoseAgreeThroughKinematics()
    {
        await using var controller = await StartAsync();
        using var client = await ConnectAsync(controller);
        await client.SendAsync("@1 1 350 -80 420 0 0 1 0;@2 3 10 20 30 0 40 5;");
        await client.ReadMessagesAsync(2);
        var s = controller.State;
        Assert.Equal(new Joints(10, 20, 30, 0, 40, 5), s.Joints);
        Assert.True(Irb120.Kinematics.Forward(s.Joints).IsSimilar(s.Pose, 1e-6, 1e-6));
        await client.SendAsync("@3 1 350 -80 420 0 0 1 0;");
        await client.ReadMessagesAsync(1);
        Assert.True(Irb120.Kinematics.Forward(controller.State.Joints).IsSimilar(new Pose(350, -80, 420, Rotation.FromQuaternion(0, 0, 1, 0)), 1e-6, 1e-6));
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task Tool_WithModel_ReportedTcpMovesWithTheToolAndTargetsAreTcp()
    {
        await using var controller = await StartAsync();
        using var client = await ConnectAsync(controller);
        await client.SendAsync("@1 8 0 0 100 1 0 0 0 1 0 0 0;");
        await client.ReadMessagesAsync(1);
        // The flange points down at 558 mm: a 100 mm tool along its Z puts the TCP at 458 mm.
        Assert.True(controller.State.Position.IsSimilar(new Vector(302, 0, 458), 1e-6), controller.State.Position.ToString());
        await client.SendAsync("@2 1 300 0 400 0 0 1 0;");
        await client.ReadMessagesAsync(1);
        Pose flange = Irb120.Kinematics.Forward(controller.State.Joints);
        Assert.True(flange.Position.IsSimilar(new Vector(300, 0, 500), 1e-6), flange.Position.ToString());
    }

    [Theory]
    [InlineData("@1 1 2000 0 300 0 0 1 0;", "cannot reach")]
    [InlineData("@1 1 1E308 0 300 0 0 1 0;", "is not a place a robot can go")]
    [InlineData("@1 3 0 0 0 0 170 0;", "beyond the limits")]
    public async Task Move_RobotCannotMake_RefusedLoggedNotAcknowledgedAndNothingAfterRuns(string request, string reason)
    {
        await using var controller = await StartAsync(instant: false);
        using var client = await ConnectAsync(controller);
        var before = controller.State;
        await client.SendAsync("@5 4 30;" + request + "@2 4 50;");
        Assert.Equal("@5 4;", (await client.ReadMessagesAsync(1))[0].ToString());
        await Eventually.TrueAsync(() => controller.RequestsExecuted == 2, "the refused move is done with", RawAbbClient.Timeout);
        Assert.Contains(reason, Assert.Single(controller.Errors), StringComparison.Ordinal);
        Assert.Equal([5], controller.ExecutedIds);
        Assert.Equal((before.Position, before.Joints, 30.0), (controller.State.Position, controller.State.Joints, controller.State.Speed));
        await controller.StopAsync();
        Assert.Equal(2, controller.RequestsExecuted);
        Assert.Equal(1, controller.AcknowledgementsSent);
    }

    [Theory]
    [InlineData("@1 6 4320000;", "longer than the 49.7 days")]
    [InlineData("@1 4 1E-9;@9 1 302 0 300 0 0 1 0;", "longer than the 49.7 days")]
    public async Task Instruction_CannotBeExecuted_RefusedLoggedAcknowledgedAndControllerServesOn(string requests, string reason)
    {
        await using var controller = await StartAsync(instant: false);
        using var client = await ConnectAsync(controller);
        var before = controller.State;
        await client.SendAsync(requests + "@2 4 50;");
        var acks = await client.ReadMessagesAsync(requests.Count(c => c == ';') + 1);
        Assert.Equal(2, acks[^1].Id);
        Assert.Contains(reason, Assert.Single(controller.Errors), StringComparison.Ordinal);
        Assert.Equal((before.Position, before.Joints, 50.0), (controller.State.Position, controller.State.Joints, controller.State.Speed));
        await controller.StopAsync();
        Assert.False(controller.IsRunning);
    }

    [Fact]
    public async Task Statement_LongerThanTheDriverReads_RefusedAndNextClientServed()
    {
        await using var controller = await StartAsync();
        using (var client = await ConnectAsync(controller))
        {
            await client.SendAsync("@1 4 " + new string('1', 5000));
            Assert.Equal("", await client.ReadToEndAsync());
        }
        Assert.Contains("statement longer than", Assert.Single(controller.Errors), StringComparison.Ordinal);
        using var second = await ConnectAsync(controller);
        await second.SendAsync("@1 4 10;");
        Assert.Equal(1, (await second.ReadMessagesAsync(1))[0].Id);
    }

    private static async Task<VirtualAbbController> StartAsync(bool instant = true)
    {
        // Not instant: a real clock, but every instruction here is either refused or takes no time.
        // The core's own planning and refusals, seen through the ABB imitation (RunsRapid = false); the RAPID twin plans nothing
        // itself (its driver does: VirtualAbbTwinSeamTests, AbbRapidTwinOnlineTests).
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = instant, RunsRapid = false });
        await controller.StartAsync();
        return controller;
    }

    private static async Task<RawAbbClient> ConnectAsync(VirtualAbbController controller)
    {
        var client = await RawAbbClient.ConnectAsync(controller.Port);
        await client.ReadHandshakeAsync();
        return client;
    }
}

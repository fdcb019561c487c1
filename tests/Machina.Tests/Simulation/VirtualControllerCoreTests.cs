using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The brand-neutral core of the virtual controllers, seen through the ABB front end: the robot model keeps joints and
/// pose consistent, at the start and as the RAPID driver moves the arm.
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

    private static async Task<VirtualAbbController> StartAsync(bool instant = true)
    {
        // The RAPID driver moves the model's arm (its refusals: AbbRapidTwinOnlineTests, VirtualAbbTwinSeamTests).
        var controller = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = instant });
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

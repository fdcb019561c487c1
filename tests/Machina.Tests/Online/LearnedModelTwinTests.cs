using System.Collections.Concurrent;
using Machina.Simulation;

namespace Machina.Tests.Online;

/// <summary>
/// A robot created without a model learns its arm from the controller when it connects (UR dashboard, ABB <c>GetSysInfo</c>,
/// KUKA <c>$MODEL_NAME[]</c>), on each brand's twin running the unchanged driver: a joint move then has the forward
/// kinematics pose, and a Cartesian move after it is accepted and executed.
/// </summary>
public class LearnedModelTwinTests
{
    /// <summary>Issues a joint move a little away from where the arm is, then a relative and an absolute move; checks poses and execution.</summary>
    /// <param name="wire">How close the arm gets to a Cartesian target: 0.01 mm on every brand (UR's wire carries 0.001 mm).</param>
    private static async Task JointThenCartesianAsync<TState>(Robot bot, VirtualController<TState> controller, RobotModel model, double wire = 0.01)
        where TState : VirtualRobotState
    {
        var executed = new ConcurrentDictionary<int, RobotState>();
        bot.ActionExecuted += (_, e) => executed[e.LastAction.Id] = e.State;
        Joints at = bot.GetCurrentAxes()!.Value;
        var joints = new Joints(at.J1 + 10, at.J2 + 5, at.J3 - 5, at.J4, at.J5 + 5, at.J6);
        Vector fk = model.Kinematics.Forward(joints).Position;

        bot.AxesTo(joints.J1, joints.J2, joints.J3, joints.J4, joints.J5, joints.J6);
        Assert.True(bot.GetIssuedState().Position!.Value.IsSimilar(fk, 0.01), $"{bot.GetIssuedState().Position} vs {fk}");
        bot.Move(0, 0, -20);
        bot.MoveTo(fk.X, fk.Y, fk.Z - 40);
        await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);
        await bot.FlushEventsAsync().WaitAsync(OnlineTestSupport.Limit);

        Assert.Equal([1, 2, 3], executed.Keys.Order());
        Assert.True(executed[1].Position!.Value.IsSimilar(fk, 0.01), $"after the joint move {executed[1].Position} vs {fk}");
        Assert.True(executed[2].Position!.Value.IsSimilar(fk + new Vector(0, 0, -20), 0.01), $"{executed[2].Position}");
        Assert.True(controller.State.Position.IsSimilar(fk + new Vector(0, 0, -40), wire), $"the arm is at {controller.State.Position}, not {fk} - 40 mm in Z");
    }

    [Fact]
    public async Task Ur_RobotWithoutModel_LearnsTheTwinsUr5e_JointThenCartesianMovesExecuted()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync();
        var log = new ConcurrentQueue<string>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b => b.Logger.AddSink(e => log.Enqueue(e.Message), LogLevel.INFO));
        try
        {
            Assert.Equal("UR5e", bot.Model!.Name);
            await bot.FlushEventsAsync().WaitAsync(OnlineTestSupport.Limit);
            Assert.Contains("The controller reports the arm \"UR5 (URSoftware 5.11.0.0 (virtual controller))\": the robot's model is now UR5e.", log);
            await JointThenCartesianAsync(bot, controller, RobotModels.Get("UR5e"));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Ur_CbSeriesTwin_LearnsUr5NotUr5e()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions
        {
            InstantExecution = true,
            Model = RobotModels.Get("UR5"),
        });
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller);
        try
        {
            Assert.Equal("UR5", bot.Model!.Name);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Abb_RobotWithoutModel_LearnsTheTwinsArm_JointThenCartesianMovesExecuted()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            RunsRapid = true,
            InstantExecution = true,
            Model = RobotModels.Get("IRB 1200-5/0.9"),
        });
        await controller.StartAsync();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller);
        try
        {
            Assert.Equal("IRB 1200-5/0.9", bot.Model!.Name);
            await JointThenCartesianAsync(bot, controller, RobotModels.Get("IRB 1200-5/0.9"));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Abb_UserModelWins_WarningNamesBoth()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { RunsRapid = true, InstantExecution = true });
        await controller.StartAsync();
        var warnings = new ConcurrentQueue<string>();
        Robot bot = Robot.Create("HelloRobot", "ABB", "IRB 140");
        bot.Logger.AddSink(e => warnings.Enqueue(e.Message), LogLevel.WARNING);
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;
        await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit);
        try
        {
            await bot.FlushEventsAsync().WaitAsync(OnlineTestSupport.Limit);
            Assert.Equal("IRB 140", bot.Model!.Name);
            Assert.Contains(warnings, w => w.StartsWith("The robot's model is IRB 140, but the controller reports the arm \"IRB 120\" (IRB 120). Machina keeps IRB 140", StringComparison.Ordinal));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Kuka_RobotWithoutModel_LearnsTheTwinsArm_JointThenCartesianMovesExecuted()
    {
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync();
        var (bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller);
        try
        {
            Assert.Equal("KR 6 R900 sixx", bot.Model!.Name);
            await JointThenCartesianAsync(bot, controller, RobotModels.Get("KR 6 R900 sixx"));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Kuka_ArmOutsideTheCatalogue_ConnectsWithoutModel_Logged()
    {
        RobotModel kr6 = RobotModels.Get("KR 6 R900 sixx");
        RobotModel custom = RobotModel.FromOpw("Workshop arm", "KUKA", kr6.Opw!.Value, kr6.MinJoints, kr6.MaxJoints);
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, Model = custom });
        var warnings = new ConcurrentQueue<string>();
        var (bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller, b => b.Logger.AddSink(e => warnings.Enqueue(e.Message), LogLevel.WARNING));
        try
        {
            await bot.FlushEventsAsync().WaitAsync(OnlineTestSupport.Limit);
            Assert.Null(bot.Model);
            Assert.Contains(warnings, w => w.StartsWith("The controller reports the arm \"#WORKSHOPARM C4\", which is not in Machina's catalogue", StringComparison.Ordinal));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

using System.Collections.Concurrent;

namespace Machina.Tests.Control;

/// <summary>What the online session does with the arm model a controller reports in its handshake.</summary>
public class LearnedModelSessionTests
{
    private static readonly Joints Start = new(0, 0, 0, 0, 90, 0);

    private static FakeDriver Driver(string? name, string? catalogueName) => new(autoAcknowledge: true)
    {
        Handshake = new DeviceHandshake("1.6.0", new Vector(374, 0, 630), Rotation.FlippedAroundY, Start, null)
        {
            ModelName = name,
            Model = catalogueName is null ? null : RobotModels.Get(catalogueName),
        },
    };

    private static (Robot Bot, ConcurrentQueue<(LogLevel Level, string Message)> Log) Connect(FakeDriver driver, string? model = null)
    {
        Robot bot = model is null ? Robot.Create("Online", "ABB") : Robot.Create("Online", "ABB", model);
        var log = new ConcurrentQueue<(LogLevel, string)>();
        bot.Logger.AddSink(e => log.Enqueue((e.Level, e.Message)), LogLevel.INFO);
        bot.DriverFactory = () => driver;
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        OnlineRobot.Flush(bot);
        return (bot, log);
    }

    [Fact]
    public async Task NoModel_ControllerNamesOne_RobotLearnsIt_JointMoveHasForwardKinematicsPose()
    {
        FakeDriver driver = Driver("IRB 120-3/0.6", "IRB 120");
        var (bot, log) = Connect(driver);
        try
        {
            Assert.Equal("IRB 120", bot.Model!.Name);
            Assert.Contains((LogLevel.INFO, "The controller reports the arm \"IRB 120-3/0.6\": the robot's model is now IRB 120."), log);
            var joints = new Joints(10, 20, -10, 0, 60, 0);
            bot.AxesTo(joints.J1, joints.J2, joints.J3, joints.J4, joints.J5, joints.J6);
            Pose fk = RobotModels.Get("IRB 120").Kinematics.Forward(joints);
            Assert.True(bot.GetIssuedState().Position!.Value.IsSimilar(fk.Position, 0.01), bot.GetIssuedState().Position.ToString());
            bot.Move(0, 0, -20);   // refused before: "the position is not known (the last motion was a joint motion)"
            await Support.Eventually.TrueAsync(() => driver.Sent.Count == 2, "both actions to be sent", OnlineRobot.Timeout);
            Assert.True(bot.GetIssuedState().Position!.Value.IsSimilar(fk.Position + new Vector(0, 0, -20), 0.01));
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }

    [Fact]
    public async Task UserModel_ControllerNamesAnother_UserModelKept_WarningNamesBoth()
    {
        var (bot, log) = Connect(Driver("IRB 1200-5/0.9", "IRB 1200-5/0.9"), "IRB 120");
        try
        {
            Assert.Equal("IRB 120", bot.Model!.Name);
            string warning = Assert.Single(log, l => l.Level == LogLevel.WARNING).Message;
            Assert.StartsWith("The robot's model is IRB 120, but the controller reports the arm \"IRB 1200-5/0.9\" (IRB 1200-5/0.9). Machina keeps IRB 120", warning);
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }

    [Fact]
    public async Task UserModel_ControllerNamesTheSame_NoWarning()
    {
        var (bot, log) = Connect(Driver("IRB 120-3/0.6", "IRB 120"), "IRB 120");
        try
        {
            Assert.Equal("IRB 120", bot.Model!.Name);
            Assert.DoesNotContain(log, l => l.Level is LogLevel.WARNING or LogLevel.ERROR);
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }

    [Fact]
    public async Task UnknownName_Logged_RobotKeepsNoModel_JointMoveStillAccepted()
    {
        var (bot, log) = Connect(Driver("IRB 99999-1/0.1", null));
        try
        {
            Assert.Null(bot.Model);
            Assert.Contains((LogLevel.WARNING, "The controller reports the arm \"IRB 99999-1/0.1\", which is not in Machina's catalogue: the robot has no model, "
                + "so joint moves have no known pose. Choose the model with SetModel before connecting (see Robot.Models)."), log);
            bot.AxesTo(0, 0, 0, 0, 80, 0);
            Assert.Null(bot.GetIssuedState().Position);
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }

    [Fact]
    public async Task NoName_NothingLearned_NothingLogged()
    {
        var (bot, log) = Connect(Driver(null, null));
        try
        {
            Assert.Null(bot.Model);
            Assert.DoesNotContain(log, l => l.Message.Contains("reports the arm", StringComparison.Ordinal));
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }
}

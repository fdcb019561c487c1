namespace Machina.Tests.Control;

/// <summary>Helpers to put a robot online against a fake driver.</summary>
internal static class OnlineRobot
{
    internal static readonly TimeSpan Timeout = TimeSpan.FromSeconds(10);

    /// <summary>An ABB robot in online mode whose connections use <paramref name="driver"/>; connected when asked.</summary>
    internal static Robot Create(FakeDriver driver, bool connect = true)
    {
        var bot = Robot.Create("Online", "ABB");
        bot.DriverFactory = () => driver;
        bot.ControlMode("online");
        if (connect)
        {
            bot.Connect("127.0.0.1", 7000);
        }
        return bot;
    }

    /// <summary>
    /// A connected robot of <paramref name="brand"/> with the arm <paramref name="model"/>, whose controller (an auto-acknowledging
    /// fake, through the brand's own codec) reports the arm at <paramref name="joints"/> and the flange pose they give.
    /// </summary>
    internal static (Robot Bot, FakeDriver Driver) CreateWithModel(string brand, string model, Joints joints)
    {
        Pose flange = RobotModels.Get(model).Kinematics.Forward(joints);
        var driver = new FakeDriver(autoAcknowledge: true) { Handshake = new DeviceHandshake("3.0.0", flange.Position, flange.Rotation, joints, null) };
        Robot bot = Robot.Create("Online", brand, model);
        bot.DriverFactory = () => driver;
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        return (bot, driver);
    }

    /// <summary>Waits (bounded) until the robot's event loop has raised everything queued so far.</summary>
    internal static void Flush(Robot bot) => bot.FlushEventsAsync().WaitAsync(Timeout).GetAwaiter().GetResult();
}

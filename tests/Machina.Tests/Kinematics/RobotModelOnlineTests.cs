using Machina.Tests.Control;
using Machina.Tests.Support;

namespace Machina.Tests.Kinematics;

public class RobotModelOnlineTests
{
    [Fact]
    public async Task Online_WithModel_RelativeMoveAfterAxesToStreamsAndWarns()
    {
        var driver = new FakeDriver(autoAcknowledge: true);
        Robot bot = Robot.Create("Online", "ABB", "IRB 120");
        bot.DriverFactory = () => driver;
        bot.ControlMode("online");
        bot.Connect("127.0.0.1", 7000);
        try
        {
            var ex = Assert.Throws<InvalidOperationException>(() => bot.SetModel("IRB 140"));
            Assert.Contains("before connecting", ex.Message);
            bot.AxesTo(0, 0, 0, 0, 1, 0);
            bot.Move(0, 0, -10);
            // The session's loop sends them on its own thread: wait for the second before reading what was sent.
            await Eventually.TrueAsync(() => driver.Sent.Count == 2, "both actions to be sent", OnlineRobot.Timeout);
            Assert.Equal(["AxesTo(0,0,0,0,1,0);", "Move(0,0,-10);"], driver.Sent.Select(a => a.ToInstruction()));
            ProgramWarning w = Assert.Single(bot.GetWarnings(), x => x.ActionId == 1);
            Assert.Equal(KinematicIssueKind.WristSingularity, w.Kind);
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }
}

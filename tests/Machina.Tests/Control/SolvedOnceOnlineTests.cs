namespace Machina.Tests.Control;

/// <summary>
/// Online, a robot with a model applies each motion on three cursors (issue, release, execution): the arm is solved once per motion,
/// by the first, and the others take its solution (Cartesian motions: the joints; joint moves: the pose and the checks).
/// </summary>
public class SolvedOnceOnlineTests
{
    private static readonly Joints Start = new(0, 0, 0, 0, 60, 0);

    [Fact]
    public async Task Streamed_CartesianAndJointMoves_EachSolvedOnce()
    {
        (Robot bot, FakeDriver driver) = OnlineRobot.CreateWithModel("ABB", "IRB 120", Start);
        Pose flange = RobotModels.Get("IRB 120").Kinematics.Forward(Start);
        try
        {
            int motions = 0;
            bot.SpeedTo(100);
            for (int i = 0; i < 10; i++)
            {
                bot.Move(0, 5, -5);          // a line: inverse kinematics along the path
                bot.Axes(1, 0, 0, 0, 0, 0);  // a joint move: forward kinematics and the checks
                bot.Rotate(0, 0, 1, 2);
                motions += 3;
            }
            bot.TransformTo(flange.Position + new Vector(0, 0, -30), flange.Rotation);
            bot.AxesTo(Start.J1, Start.J2, Start.J3, Start.J4, Start.J5, Start.J6);
            motions += 2;
            Assert.True(bot.WaitForCompletion(OnlineRobot.Timeout));
            OnlineRobot.Flush(bot);

            Assert.Equal(motions + 1, driver.Sent.Count);   // and SpeedTo
            Assert.Equal(motions, bot.KinematicSolves());
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }
}

using Machina.Tests.Support;

namespace Machina.Tests.Control;

/// <summary>
/// A refused action changes nothing: online, whether the robot's state refuses it (out of reach in strict mode, a bad value) or the
/// wire cannot carry it once applied (undone), every field of the issue cursor is as it was and nothing is sent.
/// </summary>
public class RefusedActionStateTests
{
    private static readonly Joints Home = new(0, -90, 90, -90, -90, 0);

    [Fact]
    public async Task Online_RefusedByTheStateOrByTheWire_EveryIssueCursorFieldUnchanged_NothingSent()
    {
        (Robot bot, FakeDriver driver) = OnlineRobot.CreateWithModel("UR", "UR5e", Home);
        try
        {
            bot.StrictMode(true);
            bot.Do("""
                DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50); AttachTool("pen");
                WriteDigital(1, true); SpeedTo(50); PushSettings(); SpeedTo(70); Move(0, 0, -20);
                """);
            int sent = driver.Sent.Count;
            var refusals = new (string What, Action<Robot> Issue, string Reason)[]
            {
                ("out of reach", b => b.MoveTo(5000, 0, 0), "strict mode"),
                ("beyond the joint limits", b => b.AxesTo(0, -90, 90, -90, -90, 400), "strict mode"),
                ("a negative speed", b => b.Speed(-1000), "the speed would become"),
                ("a speed the wire rounds to 0", b => b.SpeedTo(0.0001), "is 0 in its driver's 0.001 mm/s steps"),
                ("a speed the wire rounds to 0, relative", b => b.Speed(0.0001 - 70), "is 0 in its driver's 0.001 mm/s steps"),
            };
            foreach ((string what, Action<Robot> issue, string reason) in refusals)
            {
                Dictionary<string, object?> before = IssueCursor(bot);
                var refused = Assert.Throws<ActionRefusedException>(() => issue(bot));
                Assert.Contains(reason, refused.Message, StringComparison.Ordinal);
                CursorFields.AssertSame(before, IssueCursor(bot), what);
            }
            Assert.True(bot.WaitForCompletion(OnlineRobot.Timeout));
            Assert.Equal(sent, driver.Sent.Count);
        }
        finally
        {
            await bot.DisconnectAsync().WaitAsync(OnlineRobot.Timeout);
        }
    }

    private static Dictionary<string, object?> IssueCursor(Robot bot)
    {
        Dictionary<string, object?>? fields = null;
        ((IOnlineHost)bot).WithIssueCursor(cursor => fields = CursorFields.Of(cursor));
        return fields!;
    }
}

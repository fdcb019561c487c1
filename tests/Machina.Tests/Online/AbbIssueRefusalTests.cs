using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

public class AbbIssueRefusalTests
{
    public static TheoryData<RobotAction, string> Unsendable => new()
    {
        { new ActionIODigital("DÖ_漢字", true, false), "plain ASCII" },
        { new ActionIODigital(new string('a', 10_000), true, false), "at most 80 characters" },
        { new ActionIOAnalog("ao_ü", 0.5, false), "plain ASCII" },
        { new ActionIOAnalog(new string('b', 81), 0.5, false), "has 81" },
        { new ActionCustomCode("TPWrite \"é\"", false), "plain ASCII" },
        { new ActionCustomCode("a; b", false), "plain ASCII" },
        { new ActionCustomCode(" ; ", false), "cannot be empty" },
    };

    [Theory]
    [MemberData(nameof(Unsendable))]
    public void WhyCannotStream_TextTheEncoderCannotSend_NamesActionAndReason(RobotAction action, string reason)
    {
        string? why = new AbbOnline().WhyCannotStream(action);

        Assert.NotNull(why);
        Assert.StartsWith($"{action.Type} (", why);
        Assert.Contains("cannot be streamed to an ABB robot", why);
        Assert.Contains(reason, why);
        Assert.True(why.Length < 400, "the message stays readable even for a huge name");
    }

    [Fact]
    public void WhyCannotStream_SendableTexts_Null()
    {
        var online = new AbbOnline();
        RobotAction[] fine =
        [
            new ActionIODigital("DO_1", true, false), new ActionIOAnalog("AO_" + new string('x', 77), 2, false),
            new ActionCustomCode("TPWrite \"hi\";", false), new ActionCustomCode("VAR num ü := 1;", isDeclaration: true),
            new ActionMessage("DÖ \"quoted\"; 漢字"), new ActionSpeed(100, relative: false),
        ];
        Assert.All(fine, a => Assert.Null(online.WhyCannotStream(a)));
    }

    [Fact]
    public async Task WriteDigital_PinNameNotAscii_RefusedAtIssueNothingSentNextActionRuns()
    {
        await using var controller = await StartControllerAsync(new VirtualAbbControllerOptions { SpeedFactor = 20 });
        Robot bot = await ConnectAsync(controller);
        var executed = new List<int>();
        bot.ActionExecuted += (_, e) => { lock (executed) { executed.Add(e.LastAction.Id); } };

        var refused = Assert.Throws<ActionRefusedException>(() => bot.WriteDigital("DÖ_漢字", true));
        Assert.Throws<ActionRefusedException>(() => bot.WriteDigital(new string('a', 10_000), true, false));
        bot.WriteDigital("DO_1", true);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Contains("IODigital (WriteDigital(\"DÖ_漢字\",True);) cannot be streamed to an ABB robot", refused.Reason);
        Assert.Equal(-1, refused.Action.Id);
        Assert.Equal(["@1 10 \"DO_1\" 1;"], controller.ReceivedRequests.Where(r => r.Contains("DO_") || r.Contains("aaa")));
        lock (executed)
        {
            Assert.Equal([1], executed);
        }
        await bot.DisconnectAsync();
    }
}

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
        { new ActionCustomCode("TPWrite \"x\"", false), "\"TPWrite\" is not a numeric instruction code." },
        { new ActionCustomCode("TPWrite x", false), "\"TPWrite\" is not a numeric instruction code." },
        { new ActionCustomCode("@3 1 300 0 500", false), "'@' marks the id" },
        { new ActionCustomCode("7 \"unclosed", false), "a quote is never closed." },
        { new ActionCustomCode("\"x\" 7", false), "the text comes before the instruction code." },
        { new ActionCustomCode("7 \"a\" \"b\"", false), "more than one quoted text." },
        { new ActionCustomCode("7.5", false), "the instruction code 7.5 is not a whole number." },
        { new ActionCustomCode("17 1 2 3 4 5 6 7 8 9 10 11 12", false), "more than 11 numbers." },
        { new ActionCustomCode("13 1E39", false), "1E39 is beyond what a RAPID number holds" },
        { new ActionCustomCode("7 \"" + new string('y', 81) + "\"", false), "the quoted text has 81 characters." },
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
            new ActionIODigital("DO_1", true, false), new ActionIOAnalog("AO_" + new string('x', 29), 2, false),
            new ActionCustomCode("7 \"hi\";", false), new ActionCustomCode("103 0.05", false), new ActionCustomCode("14", false), new ActionCustomCode("VAR num ü := 1;", isDeclaration: true),
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

    /// <summary>
    /// A numbered pin names no ABB signal (signals are named in the IO configuration and are RAPID identifiers): offline the RAPID
    /// compiler writes a NOT SUPPORTED comment with a warning, and online the same reason refuses it at issue time, nothing sent.
    /// </summary>
    [Fact]
    public async Task WriteDigital_NumberedPin_RefusedOnlineWithTheOfflineReason_NextActionRuns()
    {
        const string Reason = "\"1\" is not a RAPID signal name; ABB signals are named in the controller's IO configuration (e.g. DO_1).";
        Robot offline = Robot.Create("Offline", "ABB");
        offline.WriteDigital(1, true);
        offline.WriteAnalog("AO_" + new string('x', 30), 0.5);
        RobotProgram program = offline.Compile(humanComments: false);
        Assert.Equal(["#1 WriteDigital(1,True); " + Reason, "#2 WriteAnalog(\"AO_xxxxxxxxxxxxxxxxxxxxxxxxxxxxxx\",0.5); \"AO_xxxxxxxxxxxxxxxxxxxxxxxxxxxxxx\" is not a RAPID signal name; ABB signals are named in the controller's IO configuration (e.g. DO_1)."],
            program.Warnings.Select(w => w.ToString()));
        Assert.Contains("    ! NOT SUPPORTED ON ABB: Turn digital IO 1 ON", program.MainFile.Lines);

        await using var controller = await StartControllerAsync();
        Robot bot = await ConnectAsync(controller);
        var refused = Assert.Throws<ActionRefusedException>(() => bot.WriteDigital(1, true));
        var refusedAnalog = Assert.Throws<ActionRefusedException>(() => bot.WriteAnalog(2, 0.5));
        bot.WriteDigital("DO_1", true);
        await bot.WaitForCompletionAsync().WaitAsync(Limit);

        Assert.Equal("IODigital (WriteDigital(1,True);) cannot be streamed to an ABB robot: " + Reason, refused.Reason);
        Assert.Equal("IOAnalog (WriteAnalog(2,0.5);) cannot be streamed to an ABB robot: " + Reason.Replace("\"1\"", "\"2\"", StringComparison.Ordinal), refusedAnalog.Reason);
        Assert.Equal(["@1 10 \"DO_1\" 1;"], controller.ReceivedRequests.Where(r => r.Contains(" 10 ") || r.Contains(" 11 ")));
        Assert.True(bot.IsConnected);
        await bot.DisconnectAsync();
    }
}

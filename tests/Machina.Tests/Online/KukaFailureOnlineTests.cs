using System.Collections.Concurrent;
using Machina.Tests.Support;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>"Executed" means the robot got there (issue 21 §1), KUKA through a Robot: a target beyond reach fails, nothing after it runs.</summary>
public class KukaFailureOnlineTests
{
    [Fact]
    public async Task Robot_UnreachableMove_ActionFailedWithTheDriversReason_LaterActionsCancelled()
    {
        await using var controller = await StartKukaAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var (bot, executed, _) = await ConnectKukaAsync(controller, b => b.ActionFailed += (_, e) => failed.TrySetResult(e));
        try
        {
            bot.SpeedTo(100);
            bot.Move(0, 0, -20);
            await bot.WaitForCompletionAsync().WaitAsync(Limit);
            int lastGood = controller.ExecutedIds[^1];
            Joints stoppedAt = controller.State.Joints;
            Vector stoppedPosition = (Vector)bot.GetCurrentPosition()!.Value;
            // The monitor reports on its own channel: a pose it sampled before the move ended can arrive after the move's
            // acknowledgement. Wait for a report of where the robot stopped, so the failure below reads that one, not an older one.
            // (CI timed out here once in session 32, not reproduced in 18 runs under load: the message now says which case it was,
            // no live pose at all or one elsewhere, and what the controller's arm and monitor say.)
            await Eventually.TrueAsync(() => bot.GetMotionState()?.Position is Vector live && live.IsSimilar(stoppedPosition, 0.05), "a live pose at the stopped position", Limit,
                () => FormattableString.Invariant($"live {bot.GetMotionState()?.Position?.ToString() ?? "none"}, stopped at {stoppedPosition}, controller {controller.State.Position}, joints {controller.State.Joints}"));

            // Both under one issue lock: the controller's failure, reported as soon as the move is sent, cannot come between them.
            bot.Do("MoveTo(2000, 0, 300); AxesTo(0, -90, 90, 0, 90, 0);");
            ActionFailedArgs e = await failed.Task.WaitAsync(Limit);
            var thrown = await Assert.ThrowsAsync<ActionFailedException>(() => bot.WaitForCompletionAsync().WaitAsync(Limit));

            Assert.Equal("MoveTo(2000,0,300);", e.Action.ToInstruction().Replace(" ", "", StringComparison.Ordinal));
            Assert.Equal("Target not reachable: no axis position within the software limit switches reaches it.", e.Reason);
            Assert.Equal("1", e.Failure.ControllerCode);
            Assert.Same(e.Action, thrown.Action);
            Assert.Equal(new[] { e.Action.Id + 1 }, e.CancelledActions.Select(a => a.Id));
            Assert.DoesNotContain(e.Action.Id, executed);
            Assert.DoesNotContain(e.Action.Id + 1, executed);
            Assert.Equal(lastGood, controller.ExecutedIds[^1]);
            Assert.Equal(stoppedAt, controller.State.Joints);
            Assert.True(e.Position is Vector at && at.IsSimilar(stoppedPosition, 0.05), e.Position?.ToString());
            Assert.True(((Vector)bot.GetCurrentPosition()!.Value).IsSimilar(stoppedPosition, 0.05));
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

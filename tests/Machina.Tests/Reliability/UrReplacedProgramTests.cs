using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// A UR driver program that a reconnection replaced but that has not finished ending (a loaded machine: the virtual UR waits
/// for it only so long) must not touch what belongs to its successor: the new program's connection back to the host and its
/// state. On a UR a program's sockets are its own and close with it. docs/reliability.md.
/// </summary>
public class UrReplacedProgramTests
{
    [Fact]
    public async Task OldProgramEndsAfterTheNewLinkIsUp_NewLinkStaysOpenAndEveryActionRunsOnce()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions
        {
            InstantExecution = true, Model = null, Faults = new VirtualFaults { After = 3, Kinds = [VirtualFault.Drop], Seed = 14104 },
        });
        await controller.StartAsync();
        await using var rig = FaultRig.Of("UR", controller.Port, controller);
        var w = rig.CreateRobot();
        await w.Bot.ConnectAsync("127.0.0.1", rig.Port).WaitAsync(Limit);
        FaultMatrixTests.IssueProgram(w.Bot, 3);
        // The drop comes with the 3rd acknowledgement, on the program's thread: the program then reads its closed socket.
        await EventuallyAsync(() => !w.Faults.IsEmpty, "the connection to drop");
        Assert.Equal([1, 2, 3], rig.ExecutedIds);

        // The first program, stopped by the next upload, is held as it ends (before its sockets close) until the new link is
        // up; the upload does not wait for it.
        using var release = new ManualResetEventSlim();
        var held = new TaskCompletionSource<Thread>(TaskCreationOptions.RunContinuationsAsynchronously);
        var ended = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        controller.Twin.StopTimeout = TimeSpan.Zero;
        controller.Twin.Ending = program =>
        {
            if (program == 1)
            {
                held.TrySetResult(Thread.CurrentThread);
                release.Wait(Limit);
            }
        };
        controller.Twin.StateChanged += () =>
        {
            if (held.Task.IsCompleted && held.Task.Result == Thread.CurrentThread)
            {
                ended.TrySetResult(); // raised once the program's sockets are closed
            }
        };
        await rig.RecoverAsync(w); // Connect again: the second program connects back
        Assert.Equal(ConnectionState.Connected, w.Bot.ConnectionState);
        Thread old = await held.Task.WaitAsync(Limit);
        Assert.True(old.IsAlive);
        release.Set();
        await ended.Task.WaitAsync(Limit);

        for (int i = 3; i < 10; i++)
        {
            w.Bot.Move(0, 0, 5);
        }
        await w.Bot.WaitForCompletionAsync().WaitAsync(Limit);
        await w.Bot.FlushEventsAsync().WaitAsync(Limit);

        Assert.Single(w.Faults); // the drop, nothing after it
        Assert.Equal(ConnectionState.Connected, w.Bot.ConnectionState);
        Assert.True(controller.IsProgramRunning, "the old program's end stopped the new one");
        FaultMatrixTests.AssertRanOnce(rig, w, 10);
        await w.Bot.DisconnectAsync();
    }
}

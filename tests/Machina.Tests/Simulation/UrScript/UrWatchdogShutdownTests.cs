using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// An RTDE watchdog's <c>stop</c> waits for the arm to stand (5 s at most) and for the program's end (the twin's stop timeout,
/// 10 s): those waits had no token, so a program slow to end kept the watchdog's stop (and the hold it set) going after the
/// controller itself was stopped (Ctrl+C on <c>machina sim ur</c>). They end now when the controller stops. The program's end
/// is held here by a test hook on its thread, and the stop timeout is ten minutes: a wait not ended by the controller's stop
/// outlasts the one-minute bound by far (no timing is measured).
/// </summary>
public sealed class UrWatchdogShutdownTests
{
    private static readonly TimeSpan Bound = TimeSpan.FromMinutes(1);

    private const string Program = "def wd():\n  rtde_set_watchdog(\"input_int_register_0\", 10, \"stop\")\n  while True:\n    sleep(1)\n  end\nend\n";

    [Fact]
    public void WatchdogStop_WaitingForAProgramSlowToEnd_EndsWhenTheTwinIsDisposed()
    {
        var clock = new ManualClock();
        // Not disposed: the program's thread may still be inside release.Wait when the test ends (the stop does not wait for it,
        // which is what is tested), and a disposed event throws there, on a thread of the twin's, ending the test host.
        var ending = new ManualResetEventSlim();
        var release = new ManualResetEventSlim();
        var twin = new UrTwinController(new UrTwinOptions { Time = clock, RealTime = true })
        {
            StopTimeout = TimeSpan.FromMinutes(10),
            Ending = _ => { ending.Set(); release.Wait(TimeSpan.FromMinutes(10)); }, // the program's thread does not end when told
        };
        try
        {
            Assert.True(twin.Start(Program), twin.Error);
            Assert.True(SpinWait.SpinUntil(() => twin.Watchdog.Armed.Count == 1 && clock.HasTimerDueIn(TimeSpan.FromMilliseconds(100)), Bound), "the watchdog was not set");
            clock.Advance(TimeSpan.FromMilliseconds(100));
            Assert.True(ending.Wait(Bound), "the watchdog did not stop the program");
            Assert.True(twin.IsHeld); // the watchdog's stop holds the arm while it waits for the program's end

            twin.Dispose();
            Assert.True(SpinWait.SpinUntil(() => !twin.IsHeld, Bound), "the watchdog's stop still waits for the program after the controller stopped");
        }
        finally
        {
            release.Set();
            twin.Dispose();
        }
    }

    [Fact]
    public async Task WatchdogStop_WaitingForAProgramSlowToEnd_DoesNotHoldTheControllersStop()
    {
        var clock = new ManualClock();
        // Not disposed: the program's thread may still be inside release.Wait when the test ends (the stop does not wait for it,
        // which is what is tested), and a disposed event throws there, on a thread of the twin's, ending the test host.
        var ending = new ManualResetEventSlim();
        var release = new ManualResetEventSlim();
        var controller = new VirtualUrController(new VirtualUrControllerOptions { TimeProvider = clock });
        try
        {
            await controller.StartAsync();
            controller.Twin.StopTimeout = TimeSpan.FromMinutes(10);
            controller.Twin.Ending = _ => { ending.Set(); release.Wait(TimeSpan.FromMinutes(10)); };
            controller.Twin.Receive(Program);
            Assert.True(SpinWait.SpinUntil(() => controller.Twin.Watchdog.Armed.Count == 1 && clock.HasTimerDueIn(TimeSpan.FromMilliseconds(100)), Bound), "the watchdog was not set");
            clock.Advance(TimeSpan.FromMilliseconds(100));
            Assert.True(ending.Wait(Bound), "the watchdog did not stop the program");
            Assert.True(controller.Twin.IsHeld);

            Task stopped = controller.StopAsync(); // what Ctrl+C on `machina sim ur` does
            Assert.Same(stopped, await Task.WhenAny(stopped, Task.Delay(Bound)));
            await stopped;
            Assert.True(SpinWait.SpinUntil(() => !controller.Twin.IsHeld, Bound), "the watchdog's stop still waits for the program after the controller stopped");
        }
        finally
        {
            release.Set();
            await controller.DisposeAsync();
        }
    }
}

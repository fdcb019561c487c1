using Machina.Cli.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Cli;

/// <summary>What <c>machina sim</c> tells from successive looks at a controller, with scripted looks and a clock that never ticks.</summary>
public sealed class ControllerActivityTests
{
    private static ControllerView View(int received, string[] requests, int executed, int[] ids, string[] pendant, string[] errors, Vector at,
        Dictionary<string, bool>? digital = null) =>
        new(received, requests, executed, ids, pendant, errors, at, new Joints(0, 0, 0, 0, 90, 0), digital ?? new Dictionary<string, bool>(), new Dictionary<string, double>());

    [Fact]
    public async Task Flush_TellsEachNewThingOnce_InTheControllersOwnWords()
    {
        var views = new Queue<ControllerView>(
        [
            View(0, [], 0, [], [], [], new Vector(1, 2, 3)),
            View(2, ["1 15 2000", "2 1 3000 1000 4000 0 31416 0"], 1, [], ["Machina driver 2.0.0 started"], [], new Vector(1, 2, 3)),
            View(3, ["1 15 2000", "2 1 3000 1000 4000 0 31416 0", "3 13 1 1 0"], 3, [1, 2], ["Machina driver 2.0.0 started"], [], new Vector(300, 100, 400),
                new Dictionary<string, bool> { ["1"] = true }),
            View(3, ["1 15 2000", "2 1 3000 1000 4000 0 31416 0", "3 13 1 1 0"], 4, [1, 2], ["Machina driver 2.0.0 started", "Program stopped: done"],
                ["protective stop"], new Vector(300, 100, 400), new Dictionary<string, bool> { ["1"] = true }),
        ]);
        ControllerView last = views.Peek();
        var lines = new List<string>();

        await using (ControllerActivity activity = ControllerActivity.Start(RobotType.UR, () => last = views.Count > 0 ? views.Dequeue() : last, lines.Add, new ManualClock()))
        {
            activity.Flush();
            activity.Flush();
            activity.Flush();
        }

        Assert.Equal(
            [
                "  pendant: Machina driver 2.0.0 started",
                "  received  AllSpeed        1 15 2000",
                "  received  MoveL           2 1 3000 1000 4000 0 31416 0",
                "  executed  1 request without an id; the tool is now at [1, 2, 3] mm, the joints at [0, 0, 0, 0, 90, 0] degrees",
                "  received  SetDigitalOut   3 13 1 1 0",
                "  executed  #1, #2; the tool is now at [300, 100, 400] mm, the joints at [0, 0, 0, 0, 90, 0] degrees",
                "  output    digital 1 on",
                "  pendant: Program stopped: done",
                "  executed  1 request without an id; the tool is now at [300, 100, 400] mm, the joints at [0, 0, 0, 0, 90, 0] degrees",
                "  ERROR     protective stop",
            ],
            lines);
    }

    [Fact]
    public async Task Quiet_TellsPendantOutputsAndErrors_ButNoRequestOrExecutedLine()
    {
        var views = new Queue<ControllerView>(
        [
            View(0, [], 0, [], [], [], new Vector(1, 2, 3)),
            View(2, ["1 15 2000", "2 1 3000 1000 4000 0 31416 0"], 1, [2], ["Machina driver 2.0.0 started"], [], new Vector(1, 2, 3),
                new Dictionary<string, bool> { ["1"] = true }),
            View(2, ["1 15 2000", "2 1 3000 1000 4000 0 31416 0"], 2, [2], ["Machina driver 2.0.0 started"], ["protective stop"], new Vector(1, 2, 3),
                new Dictionary<string, bool> { ["1"] = true }),
        ]);
        ControllerView last = views.Peek();
        var lines = new List<string>();

        await using (ControllerActivity activity = ControllerActivity.Start(RobotType.UR, () => last = views.Count > 0 ? views.Dequeue() : last, lines.Add, new ManualClock(), quiet: true))
        {
            activity.Flush();
            activity.Flush();
        }

        Assert.Equal(
            [
                "  pendant: Machina driver 2.0.0 started",
                "  output    digital 1 on",
                "  ERROR     protective stop",
            ],
            lines);
    }
}

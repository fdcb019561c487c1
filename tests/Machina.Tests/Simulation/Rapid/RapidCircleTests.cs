using System.Collections.Concurrent;
using System.Globalization;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Tests.Online;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// MoveC's limits on its points (RAPID reference, MoveC, "Limitations": the CirPoint and the ToPoint at least 1° apart seen from
/// the start point): a MoveC whose three points are almost on one line stops the task with event 50063 "Circle uncertain" before
/// the arm moves, out of real time too, in a compiled program and in the driver's MoveC alike, so that online equals offline
/// (issue 46, ABB seed 1001871: before, the compiled program ran to its end while the streamed one was refused).
/// </summary>
public class RapidCircleTests
{
    /// <summary>From where the arm stands, a MoveC to 100 mm along -x and +y through the CirPoint (<paramref name="viaX"/>, <paramref name="viaY"/>) from the start.</summary>
    private static string Arc(double viaX, double viaY) => string.Create(CultureInfo.InvariantCulture, $"""
        MODULE T
          CONST speeddata s100 := [100, 500, 5000, 1000];
          VAR robtarget p0;
          VAR robtarget via;
          VAR robtarget p1;
          PROC main()
            p0 := CRobT(\Tool:=tool0 \WObj:=wobj0);
            via := p0;
            via.trans.x := p0.trans.x + {viaX};
            via.trans.y := p0.trans.y + {viaY};
            p1 := p0;
            p1.trans.x := p0.trans.x - 100;
            p1.trans.y := p0.trans.y + 100;
            MoveC via, p1, s100, fine, tool0;
          ENDPROC
        ENDMODULE
        """);

    [Theory]
    [InlineData(-50, 50.5, 0.285)]   // 0.35 mm off the chord, between the start and the ToPoint
    [InlineData(-150, 150.5, 0.095)] // beyond the ToPoint
    [InlineData(-50, 50.8, 0.455)]
    public void MoveC_PointsLessThanOneDegreeApart_StopsWithCircleUncertain_BeforeTheArmMoves(double viaX, double viaY, double degrees)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2 });
        Pose start = twin.Arm.Tcp;
        twin.Load(("T.mod", Arc(viaX, viaY)));

        Assert.Equal(RapidProgramState.Failed, twin.Run());

        Assert.Equal(string.Create(CultureInfo.InvariantCulture,
            $"50063 Circle uncertain: seen from the start point, the CirPoint and the ToPoint of MoveC are {degrees}° apart; they must be at least 1° apart (the three points are almost on one line) (line 14, task T_ROB1)"),
            twin.Error);
        Assert.InRange(Vector.Distance(twin.Arm.Tcp.Position, start.Position), 0, 1e-9);
    }

    [Theory]
    [InlineData(-50, 52)]     // 1.1°
    [InlineData(-29.289321881, 70.710678119)] // a quarter circle
    public void MoveC_PointsOneDegreeApartOrMore_Runs(double viaX, double viaY)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Acceleration = 1.2 });
        Pose start = twin.Arm.Tcp;
        twin.Load(("T.mod", Arc(viaX, viaY)));

        Assert.Equal(RapidProgramState.Finished, twin.Run());

        Assert.True(twin.Arm.Tcp.Position.IsSimilar(start.Position + new Vector(-100, 100, 0), 1e-6), twin.Arm.Tcp.ToString());
    }

    /// <summary>
    /// ABB seed 1001871's fifth action: from (329, 21, 510) through a CirPoint behind the start (175° from the ToPoint seen from the
    /// start) to (316, 38, 510), a circle of about 1 m across that leaves the IRB 120's reach. The controller plans the circle and
    /// stops at its start with 50050; before, out of real time, the twin checked the CirPoint and the ToPoint only and ran it.
    /// </summary>
    [Fact]
    public void MoveC_CircleLeavingTheReachBetweenItsPoints_StopsWithPositionOutsideReach_BeforeTheArmMoves()
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Model = RobotModels.Get("IRB 120"), Acceleration = 1.2 });
        twin.Load(("T.mod", """
            MODULE T
              CONST speeddata s100 := [100, 500, 5000, 1000];
              PROC main()
                MoveL [[329, 21, 510], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], s100, fine, tool0;
                MoveC [[336.5, 10.5, 511], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], [[316, 38, 510], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], s100, fine, tool0;
              ENDPROC
            ENDMODULE
            """));

        Assert.Equal(RapidProgramState.Failed, twin.Run());

        Assert.StartsWith("50050 Position outside reach: ", twin.Error, StringComparison.Ordinal);
        Assert.EndsWith("(line 5, task T_ROB1)", twin.Error, StringComparison.Ordinal);
        Assert.True(twin.Arm.Tcp.Position.IsSimilar(new Vector(329, 21, 510), 1e-6), twin.Arm.Tcp.ToString());
        Assert.Equal(["MoveL"], twin.Arm.Trace.Select(t => t.Text));
    }

    [Fact]
    public void AngleDegrees_SeenFromTheStart()
    {
        Assert.Equal(90, RapidCircle.AngleDegrees(Vector.Zero, new Vector(1, 0, 0), new Vector(0, 5, 0)), 9);
        Assert.Equal(0, RapidCircle.AngleDegrees(Vector.Zero, new Vector(1, 1, 1), new Vector(3, 3, 3)), 9);
        Assert.Equal(180, RapidCircle.AngleDegrees(Vector.Zero, new Vector(-1, 0, 0), new Vector(2, 0, 0)), 9);
    }

    /// <summary>
    /// The same arc streamed: the host's pre-check passes it (the arc bulges 0.35 mm from its chord, well within reach), the
    /// driver's MoveC stops with event 50063, and the host reports the action failed with the controller's reason and code.
    /// </summary>
    [Fact]
    public async Task Streamed_NearlyStraightArc_FailsWithCircleUncertain_AsTheCompiledProgramStops()
    {
        await using VirtualAbbController controller = await OnlineTestSupport.StartControllerAsync();
        var failed = new TaskCompletionSource<ActionFailedArgs>(TaskCreationOptions.RunContinuationsAsynchronously);
        var executed = new ConcurrentQueue<int>();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b =>
        {
            b.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
            b.ActionFailed += (_, e) => failed.TrySetResult(e);
        });
        try
        {
            bot.SpeedTo(100);
            bot.TransformTo(new Vector(350, 0, 450), Rotation.FlippedAroundY);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));

            bot.ArcMotionTo(300, 50.5, 450, 250, 100, 450);
            ActionFailedArgs e = await failed.Task.WaitAsync(OnlineTestSupport.Limit);

            Assert.StartsWith("ArcMotionTo(", e.Action.ToInstruction(), StringComparison.Ordinal);
            Assert.Equal("Circle uncertain (event 50063): the arc's start point, through point and end are almost on one line (MoveC needs its through point and end at least 1° apart seen from the start).", e.Reason);
            Assert.Equal("50063", e.Failure.ControllerCode);
            Assert.DoesNotContain(e.Action.Id, executed);
            Assert.Contains(controller.Errors, m => m.StartsWith("50063 Circle uncertain: seen from the start point, the CirPoint and the ToPoint of MoveC are 0.285° apart", StringComparison.Ordinal));
            Assert.True(controller.State.Position.IsSimilar(new Vector(350, 0, 450), 0.01), controller.State.Position.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Reliability;

/// <summary>
/// An arc streamed to the virtual ABB (our RAPID driver on the RAPID twin) passes through its through point with the orientation
/// the RAPID compiler writes there: the current one for an arc of positions, the through plane's for an arc of planes (issue 46:
/// the driver used [1, 0, 0, 0], the tool pointing up, and an IRB 120 could not reach it).
/// </summary>
public class AbbArcOnlineTests
{
    private static async Task<(VirtualAbbController Controller, Robot Bot)> ConnectAsync()
    {
        VirtualAbbController controller = await OnlineTestSupport.StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true });
        try
        {
            Robot bot = await OnlineTestSupport.ConnectRobotAsync("Arc", "ABB", controller.Port, null);
            return (controller, bot);
        }
        catch
        {
            await controller.DisposeAsync();
            throw;
        }
    }

    [Fact]
    public async Task ArcOfPositions_Streamed_RunsThroughTheCurrentOrientation_AndEndsAtItsEnd()
    {
        (VirtualAbbController controller, Robot bot) = await ConnectAsync();
        await using (controller)
        {
            try
            {
                bot.TransformTo(new Vector(300, -100, 400), Rotation.FlippedAroundY);
                bot.ArcMotionTo(new Vector(375, 0, 360), new Vector(300, 100, 300));

                Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit), $"the arc did not run: {string.Join(" | ", controller.Errors)}");
                Assert.True(Vector.Distance(new Vector(300, 100, 300), controller.State.Position) < 0.01, controller.State.Position.ToString());
                Assert.Equal(["@0 31 0 0 1 0;", "@2 30 300 100 300 0 0 1 0 375 0 360;"], controller.ReceivedRequests.Where(r => r.Contains(" 30 ") || r.Contains(" 31 ")));
            }
            finally
            {
                await bot.DisconnectAsync();
            }
        }
    }

    [Fact]
    public async Task ArcOfPlanes_Streamed_SendsTheThroughPlanesOrientation()
    {
        (VirtualAbbController controller, Robot bot) = await ConnectAsync();
        await using (controller)
        {
            try
            {
                Rotation tilted = Rotation.FromAxisAngle(new Vector(1, 0, 0), 10) * Rotation.FlippedAroundY;
                bot.TransformTo(new Vector(320, -60, 420), Rotation.FlippedAroundY);
                bot.ArcMotionTo(new Plane(new Vector(360, 0, 400), tilted), new Plane(new Vector(320, 60, 420), Rotation.FlippedAroundY));

                Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit), $"the arc did not run: {string.Join(" | ", controller.Errors)}");
                Assert.True(Vector.Distance(new Vector(320, 60, 420), controller.State.Position) < 0.01, controller.State.Position.ToString());
                Assert.Equal(["@0 31 0 0 0.9962 0.0872;", "@2 30 320 60 420 0 0 1 0 360 0 400;"], controller.ReceivedRequests.Where(r => r.Contains(" 30 ") || r.Contains(" 31 ")));
            }
            finally
            {
                await bot.DisconnectAsync();
            }
        }
    }
}

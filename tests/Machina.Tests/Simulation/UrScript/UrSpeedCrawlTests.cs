using Machina.Simulation.UrScript;
using Xunit;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// A speed so small that the arm would reach its joint limit only after billions of seconds (found by UR's client library's
/// trajectory example under load, session 34): the virtual UR runs it as a crawl and the program goes on; before, the speed's
/// timer got a due time past what a timer takes and the exception ended the whole `machina sim ur` process.
/// </summary>
public sealed class UrSpeedCrawlTests
{
    [Theory]
    [InlineData("1e-13")]
    [InlineData("1e-9")]
    public void Speedj_AtACrawl_RunsAndTheProgramGoesOn(string speed)
    {
        using var bounded = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        using var twin = new UrTwinController(new UrTwinOptions { RealTime = true });
        UrProgramState state = twin.Run($$"""
            def crawl():
              speedj([{{speed}}, 0, 0, 0, 0, 0], 1.0, 0.1)
              textmsg("after")
            end
            """, bounded.Token);

        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Null(twin.Error);
        Assert.Equal(["after"], twin.Pendant.Lines);
    }
}

using System.Net;
using System.Net.Sockets;
using Machina.Simulation;
using Machina.Tests.Support;

namespace Machina.Tests.Online;

/// <summary>
/// Every brand's host checks the version of the driver it talks to when it connects (issue 46, <see cref="DriverRequirement"/>):
/// a driver of another major version or an older minor one (ABB 1.6 has no request 31 for an arc's through point, KUKA 2.0 no
/// CIRC, UR 2.x carries 0.1 mm and 1e-4 rad) is refused before anything is sent, naming both versions and what to do.
/// </summary>
public class DriverVersionCheckTests
{
    private const string AbbRemedy = "Install this Machina's driver with \"machina drivers abb --install --host H\", or load the modules "
        + "\"machina drivers abb --host H --port P --out DIR\" writes (Robot.GetDeviceDriverModules) into the motion task and start it; then connect again.";

    [Fact]
    public void Requirement_AcceptsTheShippedMinorOrLaterOfItsMajor_RefusesTheRestNamingBothVersions()
    {
        var requirement = new DriverRequirement("KUKA", new Version(2, 1), "Copy the files.");
        Assert.True(requirement.Accepts(new Version(2, 1)));
        Assert.True(requirement.Accepts(new Version(2, 3)));
        Assert.False(requirement.Accepts(new Version(2, 0)));
        Assert.False(requirement.Accepts(new Version(3, 1)));
        Assert.False(requirement.Accepts(new Version(1, 0)));
        requirement.Check("2.1");
        Assert.Equal("The Machina driver on the KUKA controller is version 2.0; this Machina needs driver 2.1 (2.1 or a later 2.x), and speaks no other. Copy the files.",
            Assert.Throws<RobotConnectionException>(() => requirement.Check("2.0")).Message);
        Assert.Equal("The Machina driver on the KUKA controller is version (none reported); this Machina needs driver 2.1 (2.1 or a later 2.x), and speaks no other. Copy the files.",
            Assert.Throws<RobotConnectionException>(() => requirement.Check("")).Message);
        Assert.Throws<RobotConnectionException>(() => requirement.Check("two"));
    }

    [Fact]
    public void Requirements_AreTheShippedDrivers()
    {
        Assert.Equal(new Version(1, 7, 0), AbbDriver.Requirement.Required);
        Assert.Contains("CONST string DRIVER_VERSION_MINOR := \"7\";", DriverFiles.Read("abb", "machina_abb_driver.mod"), StringComparison.Ordinal);
        Assert.Equal(new Version(2, 1), KukaDriver.Requirement.Required);
        Assert.Contains("\"S/@VR\", \"2.1\")", DriverFiles.Read("kuka", "machina_kuka_driver.src"), StringComparison.Ordinal);
        Assert.Equal(new Version(3, 0, 0), UrDriver.Requirement.Required);
        Assert.Contains("MACHINA_DRIVER_VERSION = [3, 0, 0]", DriverFiles.Read("ur", "machina_ur_driver.script"), StringComparison.Ordinal);
    }

    /// <summary>
    /// 1.6 has no request 31 (an arc's through point would point the tool up); 1.5 also reports no progress (before issue 46 the
    /// host took it, warned, and sent unconfirmed actions again on a reconnection: drivers before 1.7 are no longer spoken).
    /// </summary>
    [Theory]
    [InlineData(6, "1.6.0")]
    [InlineData(5, "1.5.0")]
    public async Task Abb_DriverBefore17_RefusedOnConnect_NothingSent(int minor, string version)
    {
        await using var controller = await OnlineTestSupport.StartControllerAsync(new VirtualAbbControllerOptions { InstantExecution = true, DriverVersion = new Version(1, minor, 0) });
        var bot = Robot.Create("Old", "ABB");
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;

        var e = await Assert.ThrowsAnyAsync<MachinaException>(() => bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal($"The Machina driver on the ABB controller is version {version}; this Machina needs driver 1.7.0 (1.7 or a later 1.x), and speaks no other. " + AbbRemedy, e.Message);
        Assert.False(bot.IsConnected);
        Assert.Equal(0, controller.RequestsReceived);
    }

    [Fact]
    public async Task Kuka_Driver20_WithoutCirc_RefusedOnConnect_NothingSent()
    {
        await using var controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions { InstantExecution = true, DriverVersion = new Version(2, 0) });
        var bot = Robot.Create("Old", "KUKA");
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;

        var e = await Assert.ThrowsAnyAsync<MachinaException>(() => bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal("The Machina driver on the KUKA controller is version 2.0; this Machina needs driver 2.1 (2.1 or a later 2.x), and speaks no other. "
            + "Copy the files \"machina drivers kuka --host H --port P --out DIR\" writes (Robot.GetDeviceDriverModules) to the controller and start the driver again "
            + "(docs/getting-started.md); then connect again.", e.Message);
        Assert.False(bot.IsConnected);
        Assert.Equal(0, controller.RequestsReceived);
    }

    /// <summary>
    /// The program that connects back to the host reports driver 2.0.0 (the wire of 0.1 mm and 1e-4 rad): the twin's call back is
    /// routed to this test, which answers the host as the old driver did; the host refuses it and sends it nothing.
    /// </summary>
    [Fact]
    public async Task Ur_Driver2_OfTheCoarseWire_RefusedOnConnect_NothingSent()
    {
        using var fake = new TcpListener(IPAddress.Loopback, 0);
        fake.Start();
        var callBack = new TaskCompletionSource<DnsEndPoint>(TaskCreationOptions.RunContinuationsAsynchronously);
        await using var controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions
        {
            InstantExecution = true,
            OutboundRoute = to =>
            {
                callBack.TrySetResult(to);
                return new DnsEndPoint("127.0.0.1", ((IPEndPoint)fake.LocalEndpoint).Port);
            },
        });
        var bot = Robot.Create("Old", "UR");
        bot.ControlMode("online");
        bot.ConnectTimeout = OnlineTestSupport.Limit;
        Task connecting = bot.ConnectAsync("127.0.0.1", controller.Port);

        using TcpClient twinProgram = await fake.AcceptTcpClientAsync().WaitAsync(OnlineTestSupport.Limit);
        DnsEndPoint host = await callBack.Task.WaitAsync(OnlineTestSupport.Limit);
        using var oldDriver = new TcpClient();
        await oldDriver.ConnectAsync(host.Host, host.Port).WaitAsync(OnlineTestSupport.Limit);
        NetworkStream stream = oldDriver.GetStream();
        await WireInts.WriteAsync(stream, [-50, 2, 0, 0, int.MinValue, -54, .. new int[12], int.MinValue]);

        var e = await Assert.ThrowsAnyAsync<MachinaException>(() => connecting.WaitAsync(OnlineTestSupport.Limit));

        Assert.Equal("The Machina driver on the UR controller is version 2.0.0; this Machina needs driver 3.0.0 (3.0 or a later 3.x), and speaks no other. "
            + "This Machina sends its own driver program on every connection, so another program connected back in its place: is another Machina driving this robot? "
            + "Stop it, then connect again.", e.Message);
        Assert.False(bot.IsConnected);
        // The host closed the link without sending an instruction.
        var rest = new byte[4];
        Assert.Equal(0, await stream.ReadAsync(rest).AsTask().WaitAsync(OnlineTestSupport.Limit));
    }
}

using System.Net;
using System.Net.Sockets;
using Machina.Cli.Simulation;

namespace Machina.Tests.Cli;

/// <summary>
/// <c>machina sim</c>'s relay: bytes pass both ways unchanged, a host that closes closes the controller's side, and on Linux each
/// direction is a thread of its own with a short time slice (issue 45: an RTDE package passed on at 500 Hz takes a busy core at
/// once instead of waiting for the runtime's event thread and a pool thread, each up to a time slice).
/// </summary>
public sealed class TcpRelayTests
{
    private static readonly TimeSpan Bounded = TimeSpan.FromSeconds(10);

    [Fact]
    public async Task Relay_PassesBytesBothWays_AndAHostThatClosesClosesTheControllersSide()
    {
        using var controller = new TcpListener(IPAddress.Loopback, 0);
        controller.Start();
        int target = ((IPEndPoint)controller.LocalEndpoint).Port;
        var log = new List<string>();
        await using TcpRelay relay = TcpRelay.Start(IPAddress.Loopback, 0, [new RelayRoute(0, target, "test")], l => { lock (log) { log.Add(l); } });

        using var host = new TcpClient();
        await host.ConnectAsync(IPAddress.Loopback, relay.Port).WaitAsync(Bounded);
        using Socket inside = await controller.AcceptSocketAsync().WaitAsync(Bounded);
        NetworkStream fromHost = host.GetStream();
        using var fromController = new NetworkStream(inside);

        byte[] request = [.. Enumerable.Range(0, 20_000).Select(i => (byte)(i * 7))];
        await fromHost.WriteAsync(request).AsTask().WaitAsync(Bounded);
        var got = new byte[request.Length];
        await fromController.ReadExactlyAsync(got).AsTask().WaitAsync(Bounded);
        Assert.Equal(request, got);

        byte[] answer = [1, 2, 3, 250];
        await fromController.WriteAsync(answer).AsTask().WaitAsync(Bounded);
        var back = new byte[answer.Length];
        await fromHost.ReadExactlyAsync(back).AsTask().WaitAsync(Bounded);
        Assert.Equal(answer, back);

        if (OperatingSystem.IsLinux())
        {
            string[] names = [.. Directory.GetDirectories("/proc/self/task").Select(d => Read(Path.Combine(d, "comm")).Trim())];
            Assert.Contains("relay to host", names);
            Assert.Contains("relay to contro", names); // the kernel keeps 15 characters of a thread's name
        }

        host.Close();
        var end = new byte[1];
        Assert.Equal(0, await fromController.ReadAsync(end).AsTask().WaitAsync(Bounded));
    }

    [Fact]
    public async Task OnLinux_TheRelaysThreadsHaveTheShortSlice()
    {
        if (!OperatingSystem.IsLinux() || Environment.OSVersion.Version < new Version(6, 12))
        {
            return; // older kernels take the call and keep their own slice (VirtualUrRtdeSliceTests)
        }
        using var controller = new TcpListener(IPAddress.Loopback, 0);
        controller.Start();
        int target = ((IPEndPoint)controller.LocalEndpoint).Port;
        await using TcpRelay relay = TcpRelay.Start(IPAddress.Loopback, 0, [new RelayRoute(0, target, "test")], _ => { });
        using var host = new TcpClient();
        await host.ConnectAsync(IPAddress.Loopback, relay.Port).WaitAsync(Bounded);
        using Socket inside = await controller.AcceptSocketAsync().WaitAsync(Bounded);
        // Both pumps run once a byte has crossed each way (each asks for its slice before its first read).
        await host.GetStream().WriteAsync(new byte[] { 9 }).AsTask().WaitAsync(Bounded);
        var one = new byte[1];
        using var fromController = new NetworkStream(inside);
        Assert.Equal(1, await fromController.ReadAsync(one).AsTask().WaitAsync(Bounded));
        inside.Send([8]);
        Assert.Equal(1, await host.GetStream().ReadAsync(one).AsTask().WaitAsync(Bounded));

        // Tests running beside this one may have relays of their own, whose threads may be starting or ending: the two of this relay
        // are among those that show the short slice.
        string expected = Machina.Simulation.VirtualUrRtdeSlice.SliceNanoseconds.ToString(System.Globalization.CultureInfo.InvariantCulture);
        int shortened = Directory.GetDirectories("/proc/self/task").Count(d => Read(Path.Combine(d, "comm")).Trim() is "relay to host" or "relay to contro"
            && Field(Read(Path.Combine(d, "sched")), "se.slice") == expected);
        Assert.True(shortened >= 2, $"{shortened} relay threads with a {expected} ns slice");
    }

    /// <summary>A file of a thread that may have ended meanwhile (empty then).</summary>
    private static string Read(string path)
    {
        try
        {
            return File.ReadAllText(path);
        }
        catch (Exception e) when (e is IOException or UnauthorizedAccessException)
        {
            return "";
        }
    }

    /// <summary>A "name : value" line of a thread's sched file, or empty.</summary>
    private static string Field(string sched, string name) =>
        sched.Split('\n').Select(l => l.Split(':', 2)).Where(p => p.Length == 2 && p[0].Trim() == name).Select(p => p[1].Trim()).FirstOrDefault() ?? "";
}

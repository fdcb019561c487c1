using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;

namespace Machina.Tests.Stopping;

/// <summary>
/// An ABB controller on loopback (a driver port and the monitor on port + 1, OS-chosen) whose every answer a test writes: it lets a
/// test put the driver task's and the monitor task's messages in an order a loaded controller makes only sometimes.
/// </summary>
internal sealed class ScriptedAbbController : IAsyncDisposable
{
    private static readonly TimeSpan Long = TimeSpan.FromSeconds(60);
    private readonly TcpListener _driverListener;
    private readonly TcpListener _monitorListener;
    private TcpClient? _driver;
    private TcpClient? _monitor;

    private ScriptedAbbController((TcpListener Driver, TcpListener Monitor) listeners) =>
        (_driverListener, _monitorListener) = listeners;

    internal int Port => ((IPEndPoint)_driverListener.LocalEndpoint).Port;

    internal static ScriptedAbbController Start() => new(LoopbackPorts.BindPair());

    /// <summary>Accepts the host: the driver 1.7 handshake (the arm at rest, nothing run), then the monitor and its robot type.</summary>
    internal async Task AcceptAsync()
    {
        _driver = await _driverListener.AcceptTcpClientAsync().WaitAsync(Long);
        await WriteDriverAsync("$20 1 7 0;$21 300 0 500 0 0 1 0;$22 0 0 0 0 90 0;$23 9E9 9E9 9E9 9E9 9E9 9E9;$25 0 0;");
        _monitor = await _monitorListener.AcceptTcpClientAsync().WaitAsync(Long);
        Assert.Equal("M", await ReadAsync(_monitor));
        await WriteAsync(_monitor, "$@0 101 3 IRB 120-3/0.6;");
    }

    /// <summary>Reads the driver link until <paramref name="marker"/> arrived; returns everything read.</summary>
    internal async Task<string> ReadDriverUntilAsync(string marker)
    {
        var sent = new StringBuilder();
        while (!sent.ToString().Contains(marker, StringComparison.Ordinal))
        {
            string more = await ReadAsync(_driver!);
            Assert.NotEqual("", more);
            sent.Append(more);
        }
        return sent.ToString();
    }

    internal Task WriteDriverAsync(string text) => WriteAsync(_driver!, text);

    /// <summary>
    /// Takes the host's "S" as a loaded controller may answer it: the driver task reports the move <paramref name="wireId"/> it
    /// failed on the stop (<c>$26 id 4;</c>) before the monitor task answers, and the monitor's <c>$28 3;</c> goes out only once
    /// the host has closed the driver link (the gate: that link's end), so the host never reads it.
    /// </summary>
    internal async Task StopReportFirstAsync(int wireId)
    {
        Assert.Equal("S", await ReadAsync(_monitor!));
        await WriteDriverAsync($"$26 {wireId} 4;");
        Assert.Equal("", await ReadAsync(_driver!));
        try
        {
            await WriteAsync(_monitor!, "$28 3;");
        }
        catch (IOException)
        {
            // The host closed the monitor link first.
        }
    }

    /// <summary>Reads the host's command <paramref name="command"/> on the monitor link and closes both links without answering it.</summary>
    internal async Task CloseOnAsync(string command)
    {
        Assert.Equal(command, await ReadAsync(_monitor!));
        _driver!.Dispose();
        _monitor!.Dispose();
    }

    public ValueTask DisposeAsync()
    {
        _driver?.Dispose();
        _monitor?.Dispose();
        _driverListener.Stop();
        _monitorListener.Stop();
        return ValueTask.CompletedTask;
    }

    private static async Task WriteAsync(TcpClient client, string text) =>
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text)).AsTask().WaitAsync(Long);

    /// <summary>What the host wrote next ("" once it closed the connection).</summary>
    private static async Task<string> ReadAsync(TcpClient client)
    {
        byte[] buffer = new byte[4096];
        int count = await client.GetStream().ReadAsync(buffer).AsTask().WaitAsync(Long);
        return Encoding.ASCII.GetString(buffer, 0, count);
    }
}

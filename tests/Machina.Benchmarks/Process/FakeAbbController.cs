using System.Diagnostics;
using System.Net;
using System.Net.Sockets;
using System.Text;

namespace Machina.Benchmarks;

/// <summary>
/// A minimal ABB driver for latency measurements, speaking the protocol of docs/protocol-abb.md from outside the library:
/// one client on loopback, the driver 1.6 handshake, and an immediate acknowledgement of every request. It timestamps
/// (Stopwatch, monotonic) each acknowledgement it sends and each request it receives, so that the time from an
/// acknowledgement to the arrival of the request it released can be computed without instrumenting the library.
/// No monitor port: the host then runs without motion updates, as with a controller lacking the monitor task.
/// </summary>
internal sealed class FakeAbbController : IDisposable
{
    private readonly TcpListener _listener = new(IPAddress.Loopback, 0);
    private readonly Thread _thread;
    private readonly int _expected;

    /// <summary>Starts listening; the controller serves one client until it has acknowledged <paramref name="expectedActions"/> actions.</summary>
    public FakeAbbController(int expectedActions)
    {
        _expected = expectedActions;
        _listener.Start();
        Port = ((IPEndPoint)_listener.LocalEndpoint).Port;
        ArrivalTimestamps = new long[expectedActions];
        AckTimestamps = new long[expectedActions];
        _thread = new Thread(Serve) { IsBackground = true, Name = "fake ABB controller" };
        _thread.Start();
    }

    /// <summary>The driver port.</summary>
    public int Port { get; }

    /// <summary>When each action request (id ≥ 1, in order) arrived.</summary>
    public long[] ArrivalTimestamps { get; }

    /// <summary>When the acknowledgement of each action was sent.</summary>
    public long[] AckTimestamps { get; }

    /// <summary>Number of actions acknowledged.</summary>
    public int Acknowledged { get; private set; }

    /// <summary>What went wrong, if anything.</summary>
    public string? Error { get; private set; }

    /// <summary>Waits until the client has gone or everything was acknowledged (bounded).</summary>
    public bool Wait(TimeSpan timeout) => _thread.Join(timeout);

    private void Serve()
    {
        try
        {
            using Socket client = _listener.AcceptSocket();
            client.NoDelay = true;
            client.Send(Encoding.ASCII.GetBytes("$20 1 7 0;$21 374 0 630 0 0 1 0;$22 0 0 0 0 90 0;$23 9E9 9E9 9E9 9E9 9E9 9E9;$25 0 0;"));
            var buffer = new byte[1 << 16];
            var request = new StringBuilder();
            var acks = new StringBuilder();
            while (Acknowledged < _expected)
            {
                int n = client.Receive(buffer);
                long arrived = Stopwatch.GetTimestamp();
                if (n == 0)
                {
                    return;
                }
                acks.Clear();
                var ids = new List<int>();
                for (int i = 0; i < n; i++)
                {
                    char c = (char)buffer[i];
                    if (c != ';')
                    {
                        request.Append(c);
                        continue;
                    }
                    // "@id code ..." → "@id code;" (id 0 → "code;").
                    string[] parts = request.ToString().Trim().Split(' ', 3);
                    request.Clear();
                    int id = int.Parse(parts[0].AsSpan(1), System.Globalization.CultureInfo.InvariantCulture);
                    if (id == 0)
                    {
                        acks.Append(parts[1]).Append(';');
                        continue;
                    }
                    acks.Append('@').Append(id).Append(' ').Append(parts[1]).Append(';');
                    if (id <= _expected)
                    {
                        ArrivalTimestamps[id - 1] = arrived;
                        ids.Add(id);
                    }
                }
                if (acks.Length > 0)
                {
                    client.Send(Encoding.ASCII.GetBytes(acks.ToString()));
                    long sent = Stopwatch.GetTimestamp();
                    foreach (int id in ids)
                    {
                        AckTimestamps[id - 1] = sent;
                    }
                    Acknowledged += ids.Count;
                }
            }
            // Let the client disconnect first.
            client.Receive(buffer);
        }
        catch (Exception ex) when (ex is SocketException or FormatException or IndexOutOfRangeException)
        {
            Error = ex.Message;
        }
        finally
        {
            _listener.Stop();
        }
    }

    /// <summary>
    /// With a window of one action (each acknowledgement releases exactly the next request), the latency from sending the
    /// acknowledgement of action i to receiving request i + 1, for every i; in seconds, sorted.
    /// </summary>
    public double[] ReleaseLatencies()
    {
        var latencies = new List<double>();
        for (int i = 0; i + 1 < Acknowledged; i++)
        {
            if (AckTimestamps[i] != 0 && ArrivalTimestamps[i + 1] >= AckTimestamps[i])
            {
                latencies.Add((ArrivalTimestamps[i + 1] - AckTimestamps[i]) / (double)Stopwatch.Frequency);
            }
        }
        latencies.Sort();
        return [.. latencies];
    }

    public void Dispose()
    {
        _listener.Stop();
        _thread.Join(TimeSpan.FromSeconds(5));
    }
}

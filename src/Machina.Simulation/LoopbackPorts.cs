using System.Net;
using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>Listening sockets (127.0.0.1 by default) for the virtual controllers whose driver has a second channel on port + 1 (ABB, KUKA).</summary>
internal static class LoopbackPorts
{
    private const int MaxAttempts = 50;

    /// <summary>Binds an OS-chosen port P on 127.0.0.1 for the driver and P + 1 for the monitor.</summary>
    public static (TcpListener Driver, TcpListener Monitor) BindPair() => BindPair(IPAddress.Loopback, 0);

    /// <summary>
    /// Binds port P on <paramref name="address"/> for the driver and P + 1 for the monitor: P is <paramref name="port"/>, or one the
    /// system chooses when it is 0. A <see cref="SocketException"/> when a given port is taken or the address is not this computer's.
    /// </summary>
    public static (TcpListener Driver, TcpListener Monitor) BindPair(IPAddress address, int port)
    {
        if (port != 0)
        {
            var first = new TcpListener(address, port);
            first.Start();
            try
            {
                var second = new TcpListener(address, port + 1);
                second.Start();
                return (first, second);
            }
            catch
            {
                first.Stop();
                throw;
            }
        }
        for (int attempt = 0; ; attempt++)
        {
            var driver = new TcpListener(address, 0);
            driver.Start();
            int chosen = ((IPEndPoint)driver.LocalEndpoint).Port;
            if (chosen < IPEndPoint.MaxPort)
            {
                var monitor = new TcpListener(address, chosen + 1);
                try
                {
                    monitor.Start();
                    return (driver, monitor);
                }
                catch (SocketException) when (attempt < MaxAttempts)
                {
                    // P + 1 is taken: try another pair.
                }
            }
            driver.Stop();
            if (attempt >= MaxAttempts)
            {
                throw new InvalidOperationException($"Could not find two free consecutive ports on {address}.");
            }
        }
    }
}

using System.Net;
using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>Listening sockets on 127.0.0.1 for the virtual controllers whose driver has a second channel on port + 1 (ABB, KUKA).</summary>
internal static class LoopbackPorts
{
    private const int MaxAttempts = 50;

    /// <summary>Binds an OS-chosen port P on 127.0.0.1 for the driver and P + 1 for the monitor.</summary>
    public static (TcpListener Driver, TcpListener Monitor) BindPair()
    {
        for (int attempt = 0; ; attempt++)
        {
            var driver = new TcpListener(IPAddress.Loopback, 0);
            driver.Start();
            int port = ((IPEndPoint)driver.LocalEndpoint).Port;
            if (port < IPEndPoint.MaxPort)
            {
                var monitor = new TcpListener(IPAddress.Loopback, port + 1);
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
                throw new InvalidOperationException("Could not find two free consecutive ports on 127.0.0.1.");
            }
        }
    }
}

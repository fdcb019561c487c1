using System.Globalization;
using System.Net.Sockets;

namespace Machina.Tests.Support;

/// <summary>
/// Whether the runtime's socket engine watches a socket: on Linux it registers a socket with its <c>epoll</c> instance at the
/// socket's first asynchronous operation, for good, and the kernel lists every watched descriptor in the epoll descriptor's
/// <c>/proc/self/fdinfo</c> entry (a <c>tfd:</c> line each). A watched socket wakes the engine's thread and queues a
/// thread-pool work item at every arrival, even while nothing waits for it asynchronously (issue 45).
/// </summary>
internal static class SocketEngine
{
    /// <summary>True when some epoll instance of this process watches <paramref name="socket"/>'s descriptor.</summary>
    internal static bool Watches(Socket socket)
    {
        string fd = ((long)socket.Handle).ToString(CultureInfo.InvariantCulture);
        foreach (string entry in Directory.EnumerateFiles("/proc/self/fdinfo"))
        {
            string text;
            try
            {
                text = File.ReadAllText(entry);
            }
            catch (IOException)
            {
                continue; // closed while listed
            }
            foreach (string line in text.Split('\n'))
            {
                if (line.StartsWith("tfd:", StringComparison.Ordinal) && line[4..].TrimStart().Split(' ')[0] == fd)
                {
                    return true;
                }
            }
        }
        return false;
    }
}

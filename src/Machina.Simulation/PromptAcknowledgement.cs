using System.Net.Sockets;

namespace Machina.Simulation;

/// <summary>
/// Has a connection acknowledge what it receives when it is read, not after the system's delayed-acknowledgement timer. A server
/// that has just answered a request is taken by Linux for an interactive peer and holds its acknowledgements for up to 40 ms,
/// waiting to send them with an answer; a package the client expects no answer to (an RTDE input package) is then acknowledged
/// only by that timer, and a client that runs Nagle's algorithm (SDU's ur_rtde does) keeps its next small package in its kernel
/// until then. <c>TCP_QUICKACK</c> leaves that mode until the next answer, so it is set again before each read.
/// </summary>
internal static class PromptAcknowledgement
{
    /// <summary>IPPROTO_TCP and TCP_QUICKACK of Linux's netinet/tcp.h.</summary>
    private const int TcpLevel = 6, TcpQuickAck = 12;

    /// <summary>
    /// Before a read of <paramref name="socket"/>: what the read takes is acknowledged at once (on Linux; elsewhere the system's
    /// own timing stands). A socket already closed is left alone: the read that follows tells.
    /// </summary>
    public static void BeforeRead(Socket socket)
    {
        if (!OperatingSystem.IsLinux())
        {
            return;
        }
        try
        {
            ReadOnlySpan<byte> on = [1, 0, 0, 0];
            socket.SetRawSocketOption(TcpLevel, TcpQuickAck, on);
        }
        catch (Exception e) when (e is SocketException or ObjectDisposedException)
        {
            // Closed or closing: the read says so.
        }
    }
}

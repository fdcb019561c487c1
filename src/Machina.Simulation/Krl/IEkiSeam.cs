using System.Net.Sockets;

namespace Machina.Simulation.Krl;

/// <summary>
/// Where a controller around the KRL twin watches and shapes an EthernetKRL channel, at the points a real controller's network
/// has: a client connecting, a document arriving, the program's EKI_Send, the connection ending. Used for fault injection and
/// inspection; without a seam the channel talks to its client directly.
/// </summary>
internal interface IEkiSeam
{
    /// <summary>A client connected to <paramref name="channel"/>; false refuses it (the channel closes it and listens on).</summary>
    bool Accepted(EkiChannel channel, TcpClient client);

    /// <summary>A whole document arrived on <paramref name="channel"/>: its values in order (before the program can read them; they are the reader's, read them during the call only).</summary>
    void Received(EkiChannel channel, ReadOnlySpan<(string Tag, string Value)> values);

    /// <summary>
    /// The program's EKI_Send of <paramref name="root"/> as <paramref name="document"/> (the document's UTF-8 bytes, made for this
    /// send: the seam may keep them); true when it was sent (use <see cref="EkiChannel.SendDirect"/>).
    /// </summary>
    bool Send(EkiChannel channel, string root, byte[] document);

    /// <summary>The connection of <paramref name="client"/> to <paramref name="channel"/> ended.</summary>
    void Closed(EkiChannel channel, TcpClient client);
}

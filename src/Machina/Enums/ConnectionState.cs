namespace Machina;

/// <summary>
/// Where a robot's link to its controller stands (see docs/online.md for the transitions):
/// Disconnected → Connecting → Connected ⇄ Stopped, and back to Disconnected on Disconnect or a lost link.
/// </summary>
public enum ConnectionState
{
    /// <summary>No link: offline, never connected, disconnected, or the link was lost.</summary>
    Disconnected,

    /// <summary>Opening the link and waiting for the controller's handshake.</summary>
    Connecting,

    /// <summary>Linked: issued actions are sent to the controller and acknowledged.</summary>
    Connected,

    /// <summary>Linked, but the controller stopped on its own (protective or emergency stop): nothing is sent until it runs again.</summary>
    Stopped,
}

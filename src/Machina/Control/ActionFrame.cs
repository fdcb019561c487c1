namespace Machina;

/// <summary>
/// An action as its brand's driver puts it on the wire: encoded once, when the action is issued, from the issue cursor's
/// state after it, and kept with the action until it is sent (re-encoded only when a reconnect re-targets the action).
/// </summary>
/// <param name="Bytes">What the driver sends; empty when the action sends nothing (it then counts as executed once every action before it is).</param>
/// <param name="Acknowledged">True when the controller acknowledges the action.</param>
/// <param name="Note">A warning the driver logs when it sends the frame (what the controller will not get), or null.</param>
internal sealed record ActionFrame(byte[] Bytes, bool Acknowledged, string? Note = null)
{
    /// <summary>The frame of an action that sends nothing.</summary>
    internal static ActionFrame Nothing { get; } = new([], false);
}

namespace Machina.Bridge;

public sealed partial class BridgeServer
{
    /// <summary>The messages that act on the controller at once instead of issuing instructions (the page's Pause, Resume and Stop buttons).</summary>
    internal static class Controls
    {
        /// <summary>Robot.Pause: the move under way holds where the arm is.</summary>
        internal const string Pause = "#pause";

        /// <summary>Robot.Resume: a paused robot goes on, each action running once.</summary>
        internal const string Resume = "#resume";

        /// <summary>Robot.Stop: the move under way stops where the arm is; it and every action after it fail (action-failed).</summary>
        internal const string Stop = "#stop";

        /// <summary>The control a message is (whole message, spaces around and case ignored), or null for instructions.</summary>
        internal static string? Of(string text)
        {
            string word = text.Trim();
            return word.Equals(Pause, StringComparison.OrdinalIgnoreCase) ? Pause
                : word.Equals(Resume, StringComparison.OrdinalIgnoreCase) ? Resume
                : word.Equals(Stop, StringComparison.OrdinalIgnoreCase) ? Stop
                : null;
        }
    }

    /// <summary>
    /// Runs a control out of band (a move under way is not waited for): once the controller did it every client gets
    /// <c>{"event":"control","command":"stop","user":"…"}</c>; when it cannot, the sender gets an error of kind <c>control</c>.
    /// </summary>
    private async Task ControlAsync(BridgeClient client, string control)
    {
        if (!Robot.IsConnected)
        {
            client.Send(BridgeEvents.ControllerDisconnected);
            return;
        }
        CancellationToken stopping = _stopping?.Token ?? CancellationToken.None;
        try
        {
            Task done = control switch
            {
                Controls.Pause => Robot.PauseAsync(stopping),
                Controls.Resume => Robot.ResumeAsync(stopping),
                _ => Robot.StopAsync(stopping),
            };
            await done.ConfigureAwait(false);
            Robot.Logger.Info($"Bridge: \"{client.User}\" sent {control}; the controller did it.");
            Broadcast(BridgeEvents.Control(control[1..], client.User));
        }
        catch (Exception e) when (e is MachinaException or NotSupportedException or InvalidOperationException or OperationCanceledException)
        {
            Reject(client, BridgeEvents.Error(BridgeEvents.Kinds.Control, $"{control} was not done: {e.Message}"));
        }
    }
}

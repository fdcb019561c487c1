using System.Net.Sockets;

namespace Machina.Simulation.Rapid;

internal static partial class RapidBuiltins
{
    /// <summary>
    /// Waits for a SocketAccept's connection like <see cref="Wait"/>. When the wait ends without it (its <c>\Time</c> passed, or the
    /// task stops: a restart), the accept is withdrawn, and a connection it took in the same instant is closed: left open, it
    /// was a client that no program greets or reads, waiting until its own timeout (a host that reconnected to a restarting
    /// virtual ABB waited 30 s, 2 trials in 200), and a withdrawn accept left pending took the next client from the next SocketAccept.
    /// </summary>
    private static bool WaitForAccept(RapidCall call, Task<Socket> accept, CancellationTokenSource abandon, double seconds)
    {
        bool arrived = false;
        try
        {
            arrived = Wait(call, accept, seconds);
            return arrived;
        }
        finally
        {
            if (!arrived)
            {
                abandon.Cancel();
                _ = accept.ContinueWith(static a => a.Result.Dispose(), CancellationToken.None,
                    TaskContinuationOptions.OnlyOnRanToCompletion | TaskContinuationOptions.ExecuteSynchronously, TaskScheduler.Default);
            }
        }
    }
}

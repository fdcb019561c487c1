using System.Net.Sockets;
using System.Text;

namespace Machina.Simulation;

public sealed partial class VirtualAbbController
{
    /// <summary>
    /// Sends <c>$24</c> reports in three chunks, like the RAPID monitor, until the client leaves or the controller stops; a failure
    /// report (<c>$26</c>, from the monitor's error trap) goes out before the next report.
    /// </summary>
    private async Task ReportAsync(NetworkStream stream, CancellationToken token)
    {
        try
        {
            while (true)
            {
                if (TakeFailureReport() is string failure)
                {
                    await stream.WriteAsync(Encoding.ASCII.GetBytes(failure), token).ConfigureAwait(false);
                }
                var state = State;
                var (pose, joints, axes) = AbbMessageFormat.MonitorChunks(state.Position, state.Rotation, state.Joints, state.ExternalAxesCartesian);
                await stream.WriteAsync(Encoding.ASCII.GetBytes(pose), token).ConfigureAwait(false);
                await stream.WriteAsync(Encoding.ASCII.GetBytes(joints), token).ConfigureAwait(false);
                await stream.WriteAsync(Encoding.ASCII.GetBytes(axes), token).ConfigureAwait(false);
                Interlocked.Increment(ref _monitorReportsSent);
                await Task.Delay(MonitorPeriod, Clock, token).ConfigureAwait(false);
            }
        }
        catch (Exception e) when (e is IOException or SocketException or OperationCanceledException or ObjectDisposedException)
        {
            // Client gone or stopping: wait for the next client.
        }
    }
}

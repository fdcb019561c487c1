namespace Machina;

internal abstract partial class DeviceDriver<TMessage>
{
    /// <summary>
    /// Opens the monitor link (live poses, in the driver link's messages) when the controller runs a monitor; when it does not,
    /// logs <paramref name="unavailable"/> and returns null: a controller without a monitor still streams.
    /// </summary>
    protected async Task<TcpLink?> OpenMonitorAsync(string host, int port, IMessageReader<TMessage> reader, string unavailable, CancellationToken cancellationToken)
    {
        try
        {
            return await OpenSideLinkAsync(host, port, TimeSpan.FromSeconds(2), new MonitorReceiver(this, reader), cancellationToken).ConfigureAwait(false);
        }
        catch (MachinaException)
        {
            Log.Info(unavailable);
            return null;
        }
    }

    /// <summary>The live pose a monitor message carries; false for any other message (which stops the monitor).</summary>
    protected virtual bool TryReadMotion(in TMessage message, out MotionSample sample)
    {
        sample = default;
        return false;
    }

    /// <summary>Handles a monitor message that is not a pose (e.g. the answer to an out-of-band command); false: not known, the monitor stops.</summary>
    protected virtual bool TryHandleMonitorMessage(in TMessage message) => false;

    /// <summary>A message as the log quotes it when the monitor stops on it.</summary>
    protected virtual string Describe(in TMessage message) => message?.ToString() ?? "";

    /// <summary>Reads the monitor link: live poses for the listener. A failing monitor is logged once; it never stops streaming.</summary>
    private sealed class MonitorReceiver(DeviceDriver<TMessage> driver, IMessageReader<TMessage> reader) : ILinkReceiver
    {
        private bool _stopped;

        public void OnReceived(ReadOnlySpan<byte> data)
        {
            if (_stopped)
            {
                return;
            }
            reader.Append(data);
            try
            {
                while (!_stopped && !driver.IsFailed && reader.TryRead(out TMessage message))
                {
                    if (driver.TryReadMotion(message, out MotionSample sample))
                    {
                        driver.Listener?.OnMotion(sample);
                    }
                    else if (!driver.TryHandleMonitorMessage(message))
                    {
                        Stop($"it sent {driver.Describe(message)}");
                    }
                }
            }
            catch (MachinaException ex)
            {
                Stop(ex.Message);
            }
        }

        public void OnClosed(Exception? error) => Stop(error is null ? "the controller closed the monitor connection" : error.Message);

        private void Stop(string why)
        {
            if (!_stopped && !driver.IsFailed)
            {
                _stopped = true;
                driver.Log.Warning($"Motion updates stopped: {why}.");
            }
        }
    }
}

namespace Machina;

/// <summary>
/// How the UR host learns that an action failed: a UR that cannot run an instruction (a target out of reach, a joint beyond
/// its limits) stops the program with a runtime error and never acknowledges it. RTDE then shows runtime_state stopped
/// without a safety stop, and the driver connection closes; the client interfaces (30001, 30002) send the error's text.
/// Either sign makes the action in flight fail with the controller's words (<see cref="IDeviceListener.OnFailedAfter"/>: RTDE says
/// how far the program got, the session knows which action comes next).
/// </summary>
internal sealed partial class UrDriver : ILinkReceiver
{
    /// <summary>How long a closed driver connection waits for RTDE to say whether the program stopped on an error.</summary>
    private static readonly TimeSpan StopEvidenceTimeout = TimeSpan.FromSeconds(2);

    /// <summary>
    /// How long a stopped program's failure waits for the runtime error's text from a client interface, or for RTDE to show
    /// another program playing (the driver program was replaced, not failed), before it is reported without a text.
    /// </summary>
    private static readonly TimeSpan ReplacementTimeout = TimeSpan.FromSeconds(5);

    /// <summary>The wire id of the last action sent that the controller acknowledges (ids grow in release order); 0 for none.</summary>
    private int _lastSent;

    /// <summary>The wire id of the last acknowledgement (it covers every id sent before it); 0 for none.</summary>
    private int _lastAcknowledged;
    private readonly TaskCompletionSource<string> _runtimeException = new(TaskCreationOptions.RunContinuationsAsynchronously);
    private readonly int _instance = Random.Shared.Next(1, int.MaxValue);
    private int _programFailed;

    /// <summary>True once a failure was reported: nothing more is reported by this driver.</summary>
    private bool IsProgramFailed => Volatile.Read(ref _programFailed) != 0;

    /// <summary>True when the script port is a client interface that sends robot messages (not the real-time port 30003).</summary>
    private bool ScriptPortSendsMessages => _ports.Script != UrPorts.StandardScript;

    void ILinkReceiver.OnReceived(ReadOnlySpan<byte> data) => OnReceived(data);

    /// <summary>The driver connection closed: a program stopped by a runtime error fails the action in flight; anything else is a link fault.</summary>
    void ILinkReceiver.OnClosed(Exception? error)
    {
        if (!HasHandshake || IsFailed || IsProgramFailed || !HasUnacknowledged)
        {
            if (!IsProgramFailed)
            {
                OnClosed(error);
            }
            return;
        }
        _ = AfterCloseAsync(error);
    }

    /// <summary>
    /// Waits for RTDE, or the runtime error's text on a client interface, to tell why the program's connection closed, then
    /// reports a failure or a link fault. Never throws.
    /// </summary>
    private async Task AfterCloseAsync(Exception? error)
    {
        long start = Time.GetTimestamp();
        Task<string> text = ScriptPortSendsMessages ? _runtimeException.Task : new TaskCompletionSource<string>().Task;
        try
        {
            while (!IsProgramFailed && !text.IsCompleted)
            {
                Task<RtdeSample> next;
                lock (_rtdeGate)
                {
                    if (_latest is RtdeSample s && (s.RuntimeState != RtdeSample.Playing || IsStreamBroken(s)))
                    {
                        break;
                    }
                    next = _nextSample.Task;
                }
                TimeSpan left = StopEvidenceTimeout - Time.GetElapsedTime(start);
                await Task.WhenAny(next, text).WaitAsync(left > TimeSpan.Zero ? left : TimeSpan.Zero, Time).ConfigureAwait(false);
                if (next.IsFaulted)
                {
                    await next.ConfigureAwait(false); // the RTDE link failed: no news from it
                }
            }
        }
        catch (Exception e) when (e is TimeoutException or RobotConnectionException)
        {
            // No news from RTDE: the link itself failed.
        }
        if (IsProgramFailed)
        {
            return;
        }
        if (LatestSample is RtdeSample broken && IsStreamBroken(broken))
        {
            // The program halted on its stream, not on an instruction: the link is lost.
            OnStreamBroken();
            return;
        }
        if (text.IsCompleted && LatestSample is RtdeSample last)
        {
            // The controller said why its program stopped (RTDE may still be behind): the action in flight failed.
            OnProgramStopped(last);
            return;
        }
        if (LatestSample is RtdeSample stopped && stopped.RuntimeState == RtdeSample.Stopped && !stopped.IsSafetyStop && stopped.Instance == _instance)
        {
            OnProgramStopped(stopped);
            return;
        }
        OnClosed(error);
    }

    /// <summary>
    /// The program stopped without a safety stop while actions were in flight: the first not executed fails, once. Which action
    /// that is, the session knows (its in-flight list): the driver says how far the program got (RTDE's executed id).
    /// </summary>
    private void OnProgramStopped(RtdeSample sample)
    {
        if (!HasUnacknowledgedAfter(sample.Executed) || Interlocked.Exchange(ref _programFailed, 1) != 0)
        {
            return;
        }
        _ = ReportFailureAsync(sample);
    }

    /// <summary>
    /// Reports the action in flight failed with the controller's words, unless another program took the controller (the driver
    /// program did not fail, it was replaced: a script delivered late, a program started at the pendant) or RTDE shows the
    /// program halted on a broken stream: then the link is lost instead, so that connecting again resumes from the registers.
    /// </summary>
    private async Task ReportFailureAsync(RtdeSample sample)
    {
        string? text = null;
        Task<string> reason = ScriptPortSendsMessages ? _runtimeException.Task : new TaskCompletionSource<string>().Task;
        using var done = new CancellationTokenSource();
        Task<int> replaced = OtherProgramAsync(done.Token);
        try
        {
            Task first = await Task.WhenAny(reason, replaced).WaitAsync(ReplacementTimeout, Time).ConfigureAwait(false);
            if (first == reason)
            {
                text = await reason.ConfigureAwait(false);
            }
            else
            {
                int other = await replaced.ConfigureAwait(false);
                if (other == -_instance)
                {
                    OnStreamBroken();
                    return;
                }
                Log.Warning($"The UR driver program (instance {_instance.ToString(Num.Inv)}) was replaced by another program (instance {other.ToString(Num.Inv)}).");
                OnClosed(new RobotConnectionException($"another program (instance {other.ToString(Num.Inv)}) replaced the driver program on the controller"));
                return;
            }
        }
        catch (TimeoutException)
        {
            // No text and no other program: the reason names what RTDE showed.
        }
        finally
        {
            await done.CancelAsync().ConfigureAwait(false);
        }
        if (Volatile.Read(ref _streamBroken) != 0)
        {
            return;
        }
        string because = text ?? $"the program stopped (RTDE runtime_state {sample.RuntimeState.ToString(Num.Inv)}, safety status {sample.SafetyName}) without running it";
        Listener?.OnFailedAfter(sample.Executed, because, null);
    }

    /// <summary>
    /// Completes with the instance number of another program once RTDE shows it playing, with this program's negated when RTDE
    /// shows it halted on a broken stream, or with 0 when <paramref name="cancellationToken"/> is cancelled (a broken RTDE link
    /// shows nothing more). Never throws.
    /// </summary>
    private async Task<int> OtherProgramAsync(CancellationToken cancellationToken)
    {
        while (true)
        {
            Task<RtdeSample> next;
            lock (_rtdeGate)
            {
                if (_latest is RtdeSample s && ((s.RuntimeState == RtdeSample.Playing && s.Instance != _instance) || IsStreamBroken(s)))
                {
                    return s.Instance;
                }
                next = _nextSample.Task;
            }
            try
            {
                try
                {
                    await next.WaitAsync(cancellationToken).ConfigureAwait(false);
                }
                catch (RobotConnectionException)
                {
                    await Task.Delay(Timeout.Infinite, cancellationToken).ConfigureAwait(false);
                }
            }
            catch (OperationCanceledException)
            {
                return 0;
            }
        }
    }

    /// <summary>A runtime error's text from a client interface (the script port); the first is kept.</summary>
    private void OnRuntimeException(string text)
    {
        Log.Warning("UR runtime error: " + text);
        _runtimeException.TrySetResult(text);
    }

    /// <summary>True while an action sent is not acknowledged.</summary>
    private bool HasUnacknowledged => Volatile.Read(ref _lastSent) > Volatile.Read(ref _lastAcknowledged);

    /// <summary>True when an action sent after the one with wire id <paramref name="executed"/> is not acknowledged.</summary>
    private bool HasUnacknowledgedAfter(int executed) => Volatile.Read(ref _lastSent) > Math.Max(executed, Volatile.Read(ref _lastAcknowledged));

    /// <summary>
    /// An action the controller acknowledges was sent (on the session's loop, before its bytes leave): only how far the ids got is
    /// kept, to tell at a close whether anything was in flight; the session keeps the actions themselves.
    /// </summary>
    protected override void Sent(int id) => Volatile.Write(ref _lastSent, id);

    /// <summary>An acknowledgement covers its id and every one sent before it (on the receive loop, its one writer).</summary>
    private void Acknowledged(int id)
    {
        if (id > _lastAcknowledged && id <= Volatile.Read(ref _lastSent))
        {
            Volatile.Write(ref _lastAcknowledged, id);
        }
    }
}

using System.Globalization;

namespace Machina.Simulation;

public abstract partial class VirtualController<TState>
{
    /// <summary>
    /// Requests a restart that loses the progress still runs before it restarts (<see cref="VirtualFault.RestartLosingProgress"/>);
    /// -1 when no restart is under way.
    /// </summary>
    private int _runsBeforeRestart = -1;

    /// <summary>
    /// The fault plan's RestartLosingProgress, where an acknowledgement would go out: the request ran (it is in the execution
    /// log) but its acknowledgement never leaves; the link breaks, the controller runs a seeded part of what it holds with
    /// nobody listening (their acknowledgements are lost too) and then restarts (<see cref="LoseProgress"/>). Until then it
    /// refuses every connection, so a host that reconnects meets the restarted program and learns nothing of what ran.
    /// </summary>
    private void BeginRestart()
    {
        int held = Math.Max(0, RequestsHeld);
        int runs = held == 0 ? 0 : _faultRandom!.Next(held + 1);
        lock (Gate)
        {
            _runsBeforeRestart = runs;
        }
        DropClient();
        Pendant($"fault: the link broke; {runs.ToString(CultureInfo.InvariantCulture)} of the {held.ToString(CultureInfo.InvariantCulture)} requests held run before the restart, unacknowledged");
        if (runs == 0)
        {
            Restart();
        }
    }

    /// <summary>
    /// Counts an executed request towards a pending restart (true: its acknowledgement is lost, as the link is broken); the
    /// last one before it restarts the controller.
    /// </summary>
    private bool RunsTowardsRestart()
    {
        bool restart;
        lock (Gate)
        {
            if (_runsBeforeRestart < 0)
            {
                return false;
            }
            restart = --_runsBeforeRestart <= 0;
        }
        Pendant("acknowledgement lost, the link is broken");
        if (restart)
        {
            Restart();
        }
        return true;
    }

    /// <summary>
    /// True while a restart is pending: the connection attempt is refused and the controller restarts now (a driver that runs
    /// its buffer with nobody connected acknowledges nothing, so the count may never be reached); the host connects again.
    /// </summary>
    private bool RefusesUntilRestarted()
    {
        lock (Gate)
        {
            if (_runsBeforeRestart < 0)
            {
                return false;
            }
        }
        Pendant("connection refused: the controller is restarting");
        Restart();
        return true;
    }

    /// <summary>
    /// A request a restart dropped (<see cref="DiscardHeld"/>) that the brand's driver ran anyway: it enters the execution log and
    /// counts as executed, no longer as lost. Nothing is acknowledged.
    /// </summary>
    private protected void RanOutsideBuffer(int id)
    {
        LogExecuted(id);
        Interlocked.Increment(ref _requestsExecuted);
        Changes.ChangedAfterFence();
        Interlocked.Decrement(ref _requestsLost);
    }

    /// <summary>Ends a pending restart (once): <see cref="LoseProgress"/>.</summary>
    private void Restart()
    {
        lock (Gate)
        {
            if (_runsBeforeRestart < 0)
            {
                return;
            }
            _runsBeforeRestart = -1;
        }
        LoseProgress();
    }
}

using System.Globalization;

namespace Machina.Cli.Simulation;

/// <summary>
/// Tells what a virtual controller does, in the order it does it: each request it accepted (the controller's own reading of
/// it, one per instruction, never the lines of a driver script), each action it finished with where the robot then is, pendant
/// messages (program started, stopped), errors and output changes. The virtual controllers raise no events: their public
/// inspection members are read and what is new is told (each log read from where the last look left it: <see cref="IControllerLook"/>),
/// at most once every <see cref="Period"/>, and only after the controller said something changed (<see cref="IControllerLook.Changes"/>):
/// an idle controller wakes no thread (a look on a timer woke the runtime's timer thread and two pool workers about 200 times a
/// second). A look with no such signal (a copied <see cref="ControllerView"/>) is read every <see cref="Period"/>. <see cref="Flush"/> tells the rest.
/// </summary>
internal sealed class ControllerActivity : IAsyncDisposable
{
    /// <summary>How often the controller is looked at, at most (while it changes).</summary>
    internal static readonly TimeSpan Period = TimeSpan.FromMilliseconds(50);

    private readonly Func<IControllerLook> _look;
    private readonly RobotType _brand;
    private readonly bool _quiet;
    private readonly Action<string> _log;
    private readonly Lock _gate = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;
    private readonly List<string> _texts = [];
    private readonly List<int> _ids = [];
    private long _received;
    private int _executed;
    private long _idsSeen;
    private long _pendant;
    private long _errors;
    private (object? Signals, long Writes) _outputsMark;
    private IReadOnlyDictionary<string, bool> _digital;
    private IReadOnlyDictionary<string, double> _analog;

    private ControllerActivity(RobotType brand, Func<IControllerLook> look, Action<string> log, TimeProvider time, bool quiet, bool fromStart)
    {
        _brand = brand;
        _quiet = quiet;
        _look = look;
        // Requests, pendant lines and errors carry text from the wire: shown printable, escape codes as \x1b.
        _log = line => log(PrintableText.Of(line));
        IControllerLook first = look();
        _outputsMark = first.OutputsMark;
        ControllerRobot robot = first.Robot();
        _digital = robot.DigitalOutputs;
        _analog = robot.AnalogOutputs;
        // Requests and executed ids from the start. The pendant and errors from the start too for a controller just started (its
        // program may write to the pendant before this first look: the ABB driver's version line raced it), otherwise from now on
        // (a read "since" past every count copies nothing and gives the count).
        _pendant = fromStart ? 0 : first.PendantSince(long.MaxValue, _texts);
        _errors = fromStart ? 0 : first.ErrorsSince(long.MaxValue, _texts);
        _loop = first.Changes is not null ? WhenChangedLoopAsync(time, _stop.Token) : LoopAsync(time, _stop.Token);
    }

    /// <summary>
    /// Starts telling what <paramref name="controller"/> does, one line at a time to <paramref name="log"/>; <paramref name="quiet"/>
    /// leaves out each request and executed action (their logs are then not read at all: a stream costs the looks nothing).
    /// </summary>
    internal static ControllerActivity Start(RunningController controller, Action<string> log, TimeProvider time, bool quiet = false)
    {
        var live = new LiveControllerLook(controller.Inner);
        return new(controller.Brand, () => live, log, time, quiet, fromStart: true);
    }

    /// <summary>Starts telling what a <paramref name="brand"/> controller seen through <paramref name="look"/> (whole views, one per look) does, one line at a time to <paramref name="log"/>.</summary>
    internal static ControllerActivity Start(RobotType brand, Func<ControllerView> look, Action<string> log, TimeProvider time, bool quiet = false) =>
        new(brand, () => new ControllerViewLook(look()), log, time, quiet, fromStart: false);

    /// <summary>
    /// Looks once something changed, then waits a <see cref="Period"/> (a stream's changes are told together) before it sleeps
    /// until the next change. The signal is read from each look (reading it attaches a twin's signals made since).
    /// </summary>
    private async Task WhenChangedLoopAsync(TimeProvider time, CancellationToken token)
    {
        try
        {
            while (_look().Changes is { } changes)
            {
                await changes.WhenChangedAsync(token).ConfigureAwait(false);
                changes.Take(); // before the look: a change during it sets the signal again
                Flush();
                await Task.Delay(Period, time, token).ConfigureAwait(false);
            }
        }
        catch (OperationCanceledException)
        {
        }
    }

    private async Task LoopAsync(TimeProvider time, CancellationToken token)
    {
        using var timer = new PeriodicTimer(Period, time);
        try
        {
            while (await timer.WaitForNextTickAsync(token).ConfigureAwait(false))
            {
                Flush();
            }
        }
        catch (OperationCanceledException)
        {
        }
    }

    /// <summary>
    /// Tells everything that happened since the last look. Each log is read from where the last look left it (nothing is copied
    /// when nothing is new); the robot is read only for an executed line or when the outputs' mark moved (read before the robot,
    /// so that a change after it is seen at the next look).
    /// </summary>
    internal void Flush()
    {
        lock (_gate)
        {
            IControllerLook now = _look();
            (object? Signals, long Writes) mark = now.OutputsMark;
            _pendant = Tell(now.PendantSince(_pendant, _texts), "  pendant: ");
            ControllerRobot? robot = null;
            if (!_quiet)
            {
                robot = TellRequestsAndExecuted(now);
            }
            if (mark != _outputsMark)
            {
                _outputsMark = mark;
                robot ??= now.Robot();
                TellOutputs(robot);
            }
            _errors = Tell(now.ErrorsSince(_errors, _texts), "  ERROR     ");
        }
    }

    /// <summary>Tells each request received and the actions executed since the last look; gives back the robot if it was read.</summary>
    private ControllerRobot? TellRequestsAndExecuted(IControllerLook now)
    {
        _received = now.RequestsSince(_received, _texts);
        foreach (string request in _texts)
        {
            _log($"  received  {RequestText.Describe(_brand, request)}");
        }
        _texts.Clear();
        int executed = now.RequestsExecuted;
        int newExecuted = executed - _executed;
        _idsSeen = now.ExecutedIdsSince(_idsSeen, _ids);
        ControllerRobot? robot = null;
        if (newExecuted > 0 || _ids.Count > 0)
        {
            robot = now.Robot();
            string ended = _ids.Count > 0
                ? string.Join(", ", _ids.Select(id => "#" + id.ToString(CultureInfo.InvariantCulture)))
                : $"{newExecuted.ToString(CultureInfo.InvariantCulture)} request{(newExecuted == 1 ? "" : "s")} without an id";
            _log($"  executed  {ended}; the tool is now at {robot.Position} mm, the joints at {robot.Joints} degrees");
            _ids.Clear();
        }
        _executed = executed;
        return robot;
    }

    /// <summary>Tells each text read into the list after <paramref name="prefix"/>, empties it, and gives back <paramref name="count"/>.</summary>
    private long Tell(long count, string prefix)
    {
        foreach (string text in _texts)
        {
            _log(prefix + text);
        }
        _texts.Clear();
        return count;
    }

    /// <summary>Tells each output that changed since the last look, by name.</summary>
    private void TellOutputs(ControllerRobot robot)
    {
        foreach ((string pin, bool on) in robot.DigitalOutputs.OrderBy(p => p.Key, StringComparer.Ordinal))
        {
            if (!_digital.TryGetValue(pin, out bool was) || was != on)
            {
                _log($"  output    digital {pin} {(on ? "on" : "off")}");
            }
        }
        foreach ((string pin, double value) in robot.AnalogOutputs.OrderBy(p => p.Key, StringComparer.Ordinal))
        {
            if (!_analog.TryGetValue(pin, out double was) || was != value)
            {
                _log($"  output    analog {pin} = {value.ToString("0.######", CultureInfo.InvariantCulture)}");
            }
        }
        _digital = robot.DigitalOutputs;
        _analog = robot.AnalogOutputs;
    }

    /// <summary>Stops looking, after telling the rest.</summary>
    public async ValueTask DisposeAsync()
    {
        await _stop.CancelAsync().ConfigureAwait(false);
        await _loop.ConfigureAwait(false);
        Flush();
        _stop.Dispose();
    }
}

using System.Globalization;

namespace Machina.Cli.Simulation;

/// <summary>
/// Tells what a virtual controller does, in the order it does it: each request it accepted (the controller's own reading of
/// it, one per instruction, never the lines of a driver script), each action it finished with where the robot then is, pendant
/// messages (program started, stopped), errors and output changes. The virtual controllers raise no events, so their public
/// inspection members are read every <see cref="Period"/> and the differences are told; <see cref="Flush"/> tells the rest.
/// </summary>
internal sealed class ControllerActivity : IAsyncDisposable
{
    /// <summary>How often the controller is looked at.</summary>
    internal static readonly TimeSpan Period = TimeSpan.FromMilliseconds(50);

    private readonly Func<ControllerView> _look;
    private readonly RobotType _brand;
    private readonly Action<string> _log;
    private readonly Lock _gate = new();
    private readonly CancellationTokenSource _stop = new();
    private readonly Task _loop;
    private int _received;
    private int _executed;
    private int _idsSeen;
    private int? _lastId;
    private int _pendant;
    private int _errors;
    private IReadOnlyDictionary<string, bool> _digital = new Dictionary<string, bool>();
    private IReadOnlyDictionary<string, double> _analog = new Dictionary<string, double>();

    private ControllerActivity(RobotType brand, Func<ControllerView> look, Action<string> log, TimeProvider time)
    {
        _brand = brand;
        _look = look;
        // Requests, pendant lines and errors carry text from the wire: shown printable, escape codes as \x1b.
        _log = line => log(PrintableText.Of(line));
        ControllerView first = look();
        _digital = first.DigitalOutputs;
        _analog = first.AnalogOutputs;
        _pendant = first.Pendant.Count;
        _errors = first.Errors.Count;
        _loop = LoopAsync(time, _stop.Token);
    }

    /// <summary>Starts telling what <paramref name="controller"/> does, one line at a time to <paramref name="log"/>.</summary>
    internal static ControllerActivity Start(RunningController controller, Action<string> log, TimeProvider time) =>
        Start(controller.Brand, controller.Look, log, time);

    /// <summary>Starts telling what a <paramref name="brand"/> controller seen through <paramref name="look"/> does, one line at a time to <paramref name="log"/>.</summary>
    internal static ControllerActivity Start(RobotType brand, Func<ControllerView> look, Action<string> log, TimeProvider time) =>
        new(brand, look, log, time);

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

    /// <summary>Tells everything that happened since the last look.</summary>
    internal void Flush()
    {
        lock (_gate)
        {
            ControllerView now = _look();
            foreach (string message in News(now.Pendant, ref _pendant))
            {
                _log($"  pendant: {message}");
            }
            int newRequests = now.RequestsReceived - _received;
            foreach (string request in now.Requests.TakeLast(Math.Min(Math.Max(newRequests, 0), now.Requests.Count)))
            {
                _log($"  received  {RequestText.Describe(_brand, request)}");
            }
            _received = now.RequestsReceived;
            int newExecuted = now.RequestsExecuted - _executed;
            int[] ids = NewIds(now.ExecutedIds);
            if (newExecuted > 0 || ids.Length > 0)
            {
                string ended = ids.Length > 0
                    ? string.Join(", ", ids.Select(id => "#" + id.ToString(CultureInfo.InvariantCulture)))
                    : $"{newExecuted.ToString(CultureInfo.InvariantCulture)} request{(newExecuted == 1 ? "" : "s")} without an id";
                _log($"  executed  {ended}; the tool is now at {now.Position} mm, the joints at {now.Joints} degrees");
            }
            _executed = now.RequestsExecuted;
            foreach ((string pin, bool on) in now.DigitalOutputs.OrderBy(p => p.Key, StringComparer.Ordinal))
            {
                if (!_digital.TryGetValue(pin, out bool was) || was != on)
                {
                    _log($"  output    digital {pin} {(on ? "on" : "off")}");
                }
            }
            foreach ((string pin, double value) in now.AnalogOutputs.OrderBy(p => p.Key, StringComparer.Ordinal))
            {
                if (!_analog.TryGetValue(pin, out double was) || was != value)
                {
                    _log($"  output    analog {pin} = {value.ToString("0.######", CultureInfo.InvariantCulture)}");
                }
            }
            _digital = now.DigitalOutputs;
            _analog = now.AnalogOutputs;
            foreach (string error in News(now.Errors, ref _errors))
            {
                _log($"  ERROR     {error}");
            }
        }
    }

    /// <summary>
    /// The ids executed since the last look. The controller lists only requests with an id (a UR script's own requests have none)
    /// and keeps the last <see cref="VirtualControllers.RequestsKept"/>: below that the list only grows; once full, the new ids
    /// are those after the last one seen.
    /// </summary>
    private int[] NewIds(IReadOnlyList<int> ids)
    {
        int from = Math.Min(_idsSeen, ids.Count);
        if (ids.Count >= VirtualControllers.RequestsKept && _lastId is int last)
        {
            from = 0;
            for (int k = ids.Count - 1; k >= 0; k--)
            {
                if (ids[k] == last)
                {
                    from = k + 1;
                    break;
                }
            }
        }
        _idsSeen = ids.Count;
        _lastId = ids.Count > 0 ? ids[^1] : _lastId;
        return [.. ids.Skip(from)];
    }

    /// <summary>The entries of a growing list not seen yet (the list keeps only its last entries: the count seen is capped).</summary>
    private static IEnumerable<string> News(IReadOnlyList<string> list, ref int seen)
    {
        int from = Math.Min(seen, list.Count);
        seen = list.Count;
        return list.Skip(from).ToArray();
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

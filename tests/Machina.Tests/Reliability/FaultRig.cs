using System.Collections.Concurrent;
using Machina.Simulation;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Reliability;

/// <summary>
/// One virtual controller of any brand (ABB, UR, KUKA) seen the same way by the fault tests: its port, its execution log,
/// its robot's position, and the few controls a test needs. Disposing it stops the controller.
/// </summary>
internal sealed partial class FaultRig : IAsyncDisposable
{
    /// <summary>The brands with online control, as <c>Robot.Create</c> names them.</summary>
    public static readonly string[] Brands = ["ABB", "UR", "KUKA"];

    private readonly IAsyncDisposable _controller;
    private readonly Func<IReadOnlyList<int>> _executed;
    private readonly Func<Vector> _position;
    private readonly Func<IReadOnlyList<string>> _errors;
    private readonly Func<IReadOnlyList<VirtualFault>> _injected;
    private readonly Action _resumeAnswering;

    private FaultRig(string brand, int port, IAsyncDisposable controller, Func<IReadOnlyList<int>> executed, Func<Vector> position,
        Func<IReadOnlyList<string>> errors, Func<IReadOnlyList<VirtualFault>> injected, Action resumeAnswering)
    {
        Brand = brand;
        Port = port;
        _controller = controller;
        _executed = executed;
        _position = position;
        _errors = errors;
        _injected = injected;
        _resumeAnswering = resumeAnswering;
    }

    public string Brand { get; }

    /// <summary>The port a host connects to (ABB, KUKA: the driver; UR: the script port).</summary>
    public int Port { get; }

    /// <summary>The wire ids the controller executed, in order.</summary>
    public IReadOnlyList<int> ExecutedIds => _executed();

    /// <summary>Where the simulated TCP is.</summary>
    public Vector Position => _position();

    public IReadOnlyList<string> Errors => _errors();

    public IReadOnlyList<VirtualFault> InjectedFaults => _injected();

    /// <summary>What the controller showed on its pendant (faults injected, restarts, errors), the last 1000 lines.</summary>
    public IReadOnlyList<string> PendantMessages => _controller switch
    {
        VirtualAbbController c => c.PendantMessages,
        VirtualUrController c => c.PendantMessages,
        VirtualKukaController c => c.PendantMessages,
        _ => [],
    };

    /// <summary>What the controller counted (connections, requests received, executed, acknowledged, held): a failed recovery says it.</summary>
    public string Counters => _controller switch
    {
        VirtualAbbController c => Count(c.ConnectionCount, c.RequestsReceived, c.RequestsExecuted, c.AcknowledgementsSent, c.BufferedRequestCount),
        VirtualUrController c => Count(c.ConnectionCount, c.RequestsReceived, c.RequestsExecuted, c.AcknowledgementsSent, c.BufferedRequestCount),
        VirtualKukaController c => Count(c.ConnectionCount, c.RequestsReceived, c.RequestsExecuted, c.AcknowledgementsSent, c.BufferedRequestCount),
        _ => "",
    };

    private static string Count(int connections, int received, int executed, int acknowledged, int held) =>
        $"controller: {connections} connections, {received} requests received, {executed} executed, {acknowledged} acknowledgements sent, {held} held";

    /// <summary>The controller itself (a <c>VirtualAbbController</c>, <c>VirtualUrController</c> or <c>VirtualKukaController</c>).</summary>
    public object Controller => _controller;

    public void ResumeAnswering() => _resumeAnswering();

    /// <summary>
    /// Starts a controller of <paramref name="brand"/> with instant execution, no robot model (targets are taken as they
    /// are), the given faults and room in its logs for <paramref name="logCapacity"/> requests. ABB and KUKA run their driver on
    /// the twin; KUKA, with a restart that loses the buffer, its imitation. On the RAPID twin that restart drops the client; the
    /// driver runs what reached the controller and reports it in its progress, so the host sends only the rest again.
    /// </summary>
    public static async Task<FaultRig> StartAsync(string brand, VirtualFaults faults, int logCapacity = 10_000, AcknowledgementWrites kukaWrites = AcknowledgementWrites.Whole)
    {
        switch (brand)
        {
            case "ABB":
            {
                var c = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = logCapacity });
                await c.StartAsync();
                return new FaultRig(brand, c.Port, c, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.InjectedFaults, c.ResumeAnswering);
            }
            case "UR":
            {
                var c = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = logCapacity });
                await c.StartAsync();
                return new FaultRig(brand, c.Port, c, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.InjectedFaults, c.ResumeAnswering);
            }
            case "KUKA":
            {
                // Every fault acts on the KRL twin's EthernetKRL channel; RestartLosingBuffer is a program reset: the driver runs
                // again from its first line with an empty ring and fresh progress.
                var c = new VirtualKukaController(new VirtualKukaControllerOptions
                {
                    InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = logCapacity, AcknowledgementWrites = kukaWrites,
                });
                await c.StartAsync();
                return new FaultRig(brand, c.Port, c, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.InjectedFaults, c.ResumeAnswering);
            }
            default:
                throw new ArgumentException("No virtual controller for " + brand, nameof(brand));
        }
    }

    /// <summary>A rig around a UR controller a test made itself (its own clock or options).</summary>
    public static FaultRig Of(string brand, int port, VirtualUrController c) =>
        new(brand, port, c, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.InjectedFaults, c.ResumeAnswering);

    /// <summary>An online robot of this brand, not connected yet, recording what it sees executed and every fault it reports.</summary>
    public Watched CreateRobot(Action<Robot>? configure = null, TimeProvider? time = null, int? port = null)
    {
        var bot = Robot.Create("FaultBot", Brand);
        bot.Time = time ?? TimeProvider.System; // the session takes its clock when it is made
        bot.ControlMode("online");
        bot.ConnectTimeout = Limit;
        var watched = new Watched(bot, port ?? Port);
        bot.ActionExecuted += (_, e) => watched.Executed.Enqueue(e.LastAction.Id);
        bot.ConnectionLost += (_, e) => watched.Faults.Enqueue(e.Error);
        bot.ControllerStopped += (_, e) => watched.Faults.Enqueue(e.Reason!);
        configure?.Invoke(bot);
        return watched;
    }

    /// <summary>
    /// Waits until every issued action is executed, recovering from each fault the way a user would: <c>Resume</c> after a
    /// stop, <c>Connect</c> again after a lost connection (retried while the controller refuses). Each wait is bounded by
    /// <paramref name="limit"/>; more than <paramref name="maxRecoveries"/> recoveries fail the test. Returns how many it made.
    /// </summary>
    public async Task<int> RunToCompletionAsync(Watched w, TimeSpan limit, int maxRecoveries)
    {
        for (int recoveries = 0; ; recoveries++)
        {
            try
            {
                await w.Bot.WaitForCompletionAsync().WaitAsync(limit);
                await w.Bot.FlushEventsAsync().WaitAsync(limit);
                return recoveries;
            }
            catch (MachinaException) when (recoveries < maxRecoveries)
            {
                await RecoverAsync(w);
            }
        }
    }

    /// <summary>
    /// The bound of one reconnection or resume. A reconnection to a controller that lost its buffer applies every waiting action
    /// to the cursors again, under the issue lock; with the model the robot learns on connect each one is solved (inverse
    /// kinematics): 5.6 s for 67,000 KUKA actions on a quiet machine, more than 15 s under CI's load.
    /// </summary>
    private static readonly TimeSpan RecoverLimit = TimeSpan.FromMinutes(2);

    /// <summary>Resumes a stopped robot or connects a disconnected one again, retrying a few times while the controller refuses.</summary>
    public async Task RecoverAsync(Watched w)
    {
        for (int attempt = 0; ; attempt++)
        {
            try
            {
                switch (w.Bot.ConnectionState)
                {
                    case ConnectionState.Stopped:
                        await w.Bot.ResumeAsync().WaitAsync(RecoverLimit);
                        break;
                    case ConnectionState.Disconnected:
                        await w.Bot.ConnectAsync("127.0.0.1", w.Port).WaitAsync(RecoverLimit);
                        break;
                }
                return;
            }
            catch (TimeoutException e)
            {
                // A reconnection or resume that hangs says what the controller showed meanwhile.
                throw new TimeoutException(
                    $"No recovery within {RecoverLimit.TotalSeconds} s (the robot is {w.Bot.ConnectionState}); {Counters}.\nPendant (last 40):\n  "
                    + string.Join("\n  ", PendantMessages.TakeLast(40)), e);
            }
            catch (MachinaException e) when (attempt < 20)
            {
                w.RecoveryErrors.Enqueue(e);
                await Task.Delay(10);
            }
            catch (MachinaException e)
            {
                // What the controller said is what tells a stuck driver program from a slow one: keep it with the failure.
                throw new InvalidOperationException(
                    $"No recovery after {attempt + 1} attempts: {e.Message}\n{Counters}.\nPendant (last 40):\n  "
                    + string.Join("\n  ", PendantMessages.TakeLast(40)), e);
            }
        }
    }

    public ValueTask DisposeAsync() => _controller.DisposeAsync();

    /// <summary>A robot with what its events reported: executed ids in order, and faults (lost connections, stops).</summary>
    internal sealed class Watched(Robot bot, int port)
    {
        /// <summary>Where the robot connects (the controller, or a proxy in front of it).</summary>
        public int Port { get; } = port;

        public Robot Bot { get; } = bot;

        public ConcurrentQueue<int> Executed { get; } = new();

        public ConcurrentQueue<MachinaException> Faults { get; } = new();

        /// <summary>Errors of reconnections or resumes that were retried.</summary>
        public ConcurrentQueue<MachinaException> RecoveryErrors { get; } = new();
    }
}

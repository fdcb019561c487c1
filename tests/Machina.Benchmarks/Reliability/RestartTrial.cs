#if MACHINA_ONLINE
using System.Collections.Concurrent;
using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>
/// One seeded trial of the restart schedule (issue 40): a virtual controller of a brand restarts mid-stream, losing its
/// program, its buffer and its progress (<see cref="VirtualFault.RestartLosingProgress"/> after a seeded number of
/// acknowledgements, with a seeded release window), and the host recovers the user's way (Connect again). What each side saw
/// is returned for the fault matrix to check and for the benchmark to count: the controller's own execution log (a request
/// run twice is there twice), the host's <c>ActionExecuted</c> and <c>ActionFailed</c> events, its warnings and the
/// exceptions its waits threw.
/// </summary>
internal static class RestartTrial
{
    /// <summary>The actions of the program: a move to <see cref="Start"/>, then 5 mm up each time (one request each on every brand).</summary>
    public const int Actions = 40;

    /// <summary>Where the program starts.</summary>
    public static readonly Vector Start = new(300, 100, 400);

    /// <summary>The brands with online control, as <c>Robot.Create</c> names them.</summary>
    public static readonly string[] Brands = ["ABB", "UR", "KUKA"];

    /// <summary>What one trial saw.</summary>
    internal sealed record Result(string Brand, int Seed, int RestartAfter, int BlockSize, int PendingCount)
    {
        /// <summary>The controller's execution log: wire ids in the order its arm ran them.</summary>
        public IReadOnlyList<int> ControllerLog { get; init; } = [];

        /// <summary>Ids the host reported executed (<c>ActionExecuted</c>), in order.</summary>
        public IReadOnlyList<int> Executed { get; init; } = [];

        /// <summary>The host's <c>ActionFailed</c> events, in order.</summary>
        public IReadOnlyList<ActionFailedArgs> Failed { get; init; } = [];

        /// <summary>The host's log at WARNING and above.</summary>
        public IReadOnlyList<string> Warnings { get; init; } = [];

        /// <summary>What the waits for completion threw other than a lost connection (the restart's report).</summary>
        public IReadOnlyList<MachinaException> WaitFailures { get; init; } = [];

        /// <summary>Connections made again after a lost one.</summary>
        public int Recoveries { get; init; }

        /// <summary>Actions still pending at the end (none expected).</summary>
        public int Pending { get; init; }

        /// <summary>Where the controller's arm ended, and where the host's execution state says it is.</summary>
        public Vector ControllerPosition { get; init; }

        public Vector ExecutedPosition { get; init; }

        public IReadOnlyList<VirtualFault> Injected { get; init; } = [];

        public IReadOnlyList<string> ControllerErrors { get; init; } = [];

        public IReadOnlyList<string> HostLog { get; init; } = [];

        public IReadOnlyList<string> Pendant { get; init; } = [];

        /// <summary>Ids the controller ran more than once.</summary>
        public IReadOnlyList<int> RunTwice => [.. ControllerLog.GroupBy(id => id).Where(g => g.Count() > 1).Select(g => g.Key).Order()];

        /// <summary>Ids that never ended on the host (neither executed nor failed).</summary>
        public IReadOnlyList<int> Unended => [.. Enumerable.Range(1, Actions).Except(Executed).Except(Failed.Select(f => f.Action.Id))];

        /// <summary>Everything the trial saw, for a failure message.</summary>
        public string Describe() =>
            $"{Brand} seed {Seed}: restart after {RestartAfter} acknowledgements, block {BlockSize}, pending {PendingCount}\n"
            + $"controller log: {string.Join(' ', ControllerLog)}\nhost executed: {string.Join(' ', Executed)}\n"
            + $"host failed: {string.Join(' ', Failed.Select(f => f.Action.Id))}\nrun twice: {string.Join(' ', RunTwice)}\n"
            + $"host log:\n  {string.Join("\n  ", HostLog)}\npendant (last 30):\n  {string.Join("\n  ", Pendant.TakeLast(30))}";
    }

    /// <summary>
    /// Runs the trial of <paramref name="seed"/> on a fresh controller of <paramref name="brand"/>; <paramref name="configure"/>
    /// sets the robot up (a restart policy) before it connects. Each wait is bounded by <paramref name="limit"/>.
    /// </summary>
    public static async Task<Result> RunAsync(string brand, int seed, Action<Robot>? configure, TimeSpan limit)
    {
        var random = new Random(seed);
        int restartAfter = random.Next(3, 30);
        int blockSize = random.Next(2, 17);
        int pendingCount = random.Next(1, 7);
        var faults = new VirtualFaults { After = restartAfter, Kinds = [VirtualFault.RestartLosingProgress], Seed = seed };
        await using Controller controller = await Controller.StartAsync(brand, faults);

        var bot = Robot.Create("RestartBot", brand);
        bot.ControlMode("online");
        bot.ConnectTimeout = limit;
        bot.BlockSize = blockSize;
        bot.PendingCount = pendingCount;
        var executed = new ConcurrentQueue<int>();
        var failed = new ConcurrentQueue<ActionFailedArgs>();
        var log = new ConcurrentQueue<LogEntry>();
        bot.ActionExecuted += (_, e) => executed.Enqueue(e.LastAction.Id);
        bot.ActionFailed += (_, e) => failed.Enqueue(e);
        using IDisposable sink = bot.Logger.AddSink(log.Enqueue, LogLevel.DEBUG);
        configure?.Invoke(bot);
        try
        {
            await bot.ConnectAsync("127.0.0.1", controller.Port).WaitAsync(limit);
            bot.MoveTo(Start.X, Start.Y, Start.Z);
            for (int i = 1; i < Actions; i++)
            {
                bot.Move(0, 0, 5);
            }
            var waitFailures = new List<MachinaException>();
            int recoveries = 0;
            for (int round = 0; ; round++)
            {
                try
                {
                    await bot.WaitForCompletionAsync().WaitAsync(limit);
                    await bot.FlushEventsAsync().WaitAsync(limit);
                    break;
                }
                catch (ActionFailedException e) when (round < 10)
                {
                    waitFailures.Add(e); // the restart's report: the wait after it throws it once
                }
                catch (MachinaException) when (round < 10 && bot.ConnectionState == ConnectionState.Disconnected)
                {
                    await ReconnectAsync(bot, controller.Port, limit);
                    recoveries++;
                }
            }
            return new Result(brand, seed, restartAfter, blockSize, pendingCount)
            {
                ControllerLog = controller.ExecutedIds(),
                Executed = [.. executed],
                Failed = [.. failed],
                Warnings = [.. log.Where(e => e.Level >= LogLevel.WARNING).Select(e => e.Message)],
                WaitFailures = waitFailures,
                Recoveries = recoveries,
                Pending = bot.GetPendingActions().Count,
                ControllerPosition = controller.Position(),
                ExecutedPosition = bot.GetExecutedState().Position ?? Vector.Zero,
                Injected = controller.Injected(),
                ControllerErrors = controller.Errors(),
                HostLog = [.. log.Select(e => $"{e.Level} {e.Message}")],
                Pendant = controller.Pendant(),
            };
        }
        catch (Exception e) when (e is not TrialException)
        {
            throw new TrialException($"{brand} seed {seed} (restart after {restartAfter}, block {blockSize}, pending {pendingCount}) did not end: {e.Message}\n"
                + $"host log:\n  {string.Join("\n  ", log.Select(l => $"{l.Level} {l.Message}"))}\npendant (last 30):\n  {string.Join("\n  ", controller.Pendant().TakeLast(30))}", e);
        }
        finally
        {
            await bot.DisposeAsync();
        }
    }

    /// <summary>Connects again, retrying while the restarting controller refuses (at most 100 attempts, 20 ms apart).</summary>
    private static async Task ReconnectAsync(Robot bot, int port, TimeSpan limit)
    {
        for (int attempt = 0; ; attempt++)
        {
            try
            {
                await bot.ConnectAsync("127.0.0.1", port).WaitAsync(limit);
                return;
            }
            catch (MachinaException) when (attempt < 100)
            {
                await Task.Delay(20);
            }
        }
    }

    /// <summary>A trial that could not end (a recovery or wait that failed for good), with what the host and the controller said.</summary>
    internal sealed class TrialException(string message, Exception inner) : Exception(message, inner);

    /// <summary>A virtual controller of any brand, seen the same way.</summary>
    private sealed class Controller(IAsyncDisposable controller, int port, Func<IReadOnlyList<int>> executed, Func<Vector> position,
        Func<IReadOnlyList<string>> errors, Func<IReadOnlyList<string>> pendant, Func<IReadOnlyList<VirtualFault>> injected) : IAsyncDisposable
    {
        public int Port { get; } = port;

        public Func<IReadOnlyList<int>> ExecutedIds { get; } = executed;

        public Func<Vector> Position { get; } = position;

        public Func<IReadOnlyList<string>> Errors { get; } = errors;

        public Func<IReadOnlyList<string>> Pendant { get; } = pendant;

        public Func<IReadOnlyList<VirtualFault>> Injected { get; } = injected;

        public static async Task<Controller> StartAsync(string brand, VirtualFaults faults)
        {
            switch (brand)
            {
                case "ABB":
                {
                    var c = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = 1000 });
                    await c.StartAsync();
                    return new Controller(c, c.Port, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.PendantMessages, () => c.InjectedFaults);
                }
                case "UR":
                {
                    var c = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = 1000 });
                    await c.StartAsync();
                    return new Controller(c, c.Port, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.PendantMessages, () => c.InjectedFaults);
                }
                case "KUKA":
                {
                    var c = new VirtualKukaController(new VirtualKukaControllerOptions { InstantExecution = true, Model = null, Faults = faults, RequestLogCapacity = 1000 });
                    await c.StartAsync();
                    return new Controller(c, c.Port, () => c.ExecutedIds, () => c.State.Position, () => c.Errors, () => c.PendantMessages, () => c.InjectedFaults);
                }
                default:
                    throw new ArgumentException("No virtual controller for " + brand, nameof(brand));
            }
        }

        public ValueTask DisposeAsync() => controller.DisposeAsync();
    }
}
#endif

using Machina.Simulation;

namespace Machina.Benchmarks;

/// <summary>
/// Issue 45's "plain program", as a user writes it: <c>Robot.Create</c>, online, <c>ConnectAsync</c> to the brand's twin
/// (in this process, instant execution, default options: no model), <c>SpeedTo(200)</c>, <c>Move(±1, 0, 0)</c> for every
/// action, <c>WaitForCompletionAsync</c>, default window. Creating the robot and connecting are part of the timed work, as in
/// the program; the twin is started outside it. The row's CPU time (host and twin together, the whole process) over the size
/// is the processor time per action the issue's ≤ 20 µs target is stated for.
/// With <paramref name="connectOnce"/> (the <c>steady-</c> rows) the robot is created and connected once, before the warm-ups, and
/// every run streams on it: the stream of a program that stays connected, without the connect and disconnect code that each
/// <c>plain-</c> run calls anew (which the JIT promotes only after tens of runs, inside the measured ones).
/// </summary>
internal sealed class PlainProgramScenario(RobotType brand, bool connectOnce = false) : Scenario
{
    private IAsyncDisposable? _twin;
    private Robot? _bot;
    private int _port;
    private bool _byThread;

    /// <summary>How many moves a small run streams (<see cref="SmallRun"/>): a block of the default window.</summary>
    internal const int SmallRunSize = 8;

    public override string Name => (connectOnce ? "steady-" : "plain-") + brand.ToString().ToLowerInvariant();

    public override string Title => connectOnce
        ? $"Plain program's stream on a robot connected once to the {brand} twin (instant, no model): SpeedTo(200), Move(±1,0,0) per action, WaitForCompletion"
        : $"Plain program: Robot.Create, online, connect to the {brand} twin (instant, no model), SpeedTo(200), "
            + "Move(±1,0,0) per action, WaitForCompletion, default window";

    public override int TargetSize => 20_000;

    public override IReadOnlyList<int> ScalingSizes => [];

    public override Target Target => Catalog.PlainProgramTarget;

    public override bool MultiThreaded => true;

    public override Func<object?> Prepare(int size)
    {
        int port;
        switch (brand)
        {
            case RobotType.ABB:
                var abb = new VirtualAbbController(new VirtualAbbControllerOptions { InstantExecution = true });
                abb.StartAsync().GetAwaiter().GetResult();
                (_twin, port) = (abb, abb.Port);
                break;
            case RobotType.UR:
                var ur = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
                ur.StartAsync().GetAwaiter().GetResult();
                (_twin, port) = (ur, ur.Port);
                break;
            case RobotType.KUKA:
                var kuka = new VirtualKukaController(new VirtualKukaControllerOptions { InstantExecution = true });
                kuka.StartAsync().GetAwaiter().GetResult();
                (_twin, port) = (kuka, kuka.Port);
                break;
            default:
                throw new NotSupportedException($"{brand} has no twin.");
        }
        _port = port;
        // Reading /proc costs processor time inside the timed work: only when asked.
        bool byThread = Environment.GetEnvironmentVariable("MACHINA_BENCH_THREADS") == "1";
        _byThread = byThread;
        if (connectOnce)
        {
            Robot connected = Connected(port);
            return () =>
            {
                Dictionary<int, ThreadCpu.ThreadTime>? before = byThread ? ThreadCpu.Read() : null;
                int solvesBefore = byThread ? connected.KinematicSolves() : 0;
                Stream(connected, size);
                if (before is not null)
                {
                    Console.Error.WriteLine($"{Name}: streaming: {ThreadCpu.Text(ThreadCpu.Difference(before, ThreadCpu.Read()), size)}; "
                        + $"kinematic solves {connected.KinematicSolves() - solvesBefore} (the three cursors)");
                }
                return null;
            };
        }
        return () =>
        {
            Dictionary<int, ThreadCpu.ThreadTime>? threadsBefore = byThread ? ThreadCpu.Read() : null;
            // A robot per run, as a program makes one: the previous run's robot is disconnected first.
            _bot?.DisconnectAsync().GetAwaiter().GetResult();
            long connectStart = System.Diagnostics.Stopwatch.GetTimestamp();
            Robot bot = Connected(port);
            TimeSpan connect = System.Diagnostics.Stopwatch.GetElapsedTime(connectStart);
            Dictionary<int, ThreadCpu.ThreadTime>? threadsConnected = byThread ? ThreadCpu.Read() : null;
            Stream(bot, size);
            if (threadsBefore is not null && threadsConnected is not null)
            {
                Console.Error.WriteLine($"{Name}: connect {connect.TotalMilliseconds:0} ms, processor time by thread while connecting: "
                    + $"{ThreadCpu.Text(ThreadCpu.Difference(threadsBefore, threadsConnected))}; streaming: {ThreadCpu.Text(ThreadCpu.Difference(threadsConnected, ThreadCpu.Read()), size)}; "
                    + $"kinematic solves {bot.KinematicSolves()} (the three cursors)");
            }
            return null;
        };
    }

    /// <summary>
    /// The run's calls made once, with <see cref="SmallRunSize"/> moves: on the robot connected once (<c>steady-</c>), or, as a
    /// <c>plain-</c> run does, the previous robot disconnected and a new one created and connected.
    /// With <c>MACHINA_BENCH_THREADS=1</c> it also reads the robot's solve count, as a run's line does (the line's text is the
    /// harness's bookkeeping, warmed apart).
    /// </summary>
    public override Action? SmallRun() => () =>
    {
        Robot bot;
        if (connectOnce)
        {
            bot = _bot!;
        }
        else
        {
            _bot?.DisconnectAsync().GetAwaiter().GetResult();
            bot = Connected(_port);
        }
        Stream(bot, SmallRunSize);
        if (_byThread)
        {
            _ = bot.KinematicSolves();
        }
    };

    /// <summary>A robot created, online and connected to the twin at <paramref name="port"/> (kept, so that the next run disconnects it).</summary>
    private Robot Connected(int port)
    {
        var bot = Robot.Create("Plain", brand.ToString());
        _bot = bot;
        bot.ControlMode("online");
        bot.ConnectAsync("127.0.0.1", port).GetAwaiter().GetResult();
        return bot;
    }

    /// <summary>The program's body on a connected robot: <c>SpeedTo(200)</c>, <paramref name="size"/> moves of ±1 mm, waiting for completion.</summary>
    internal static void Stream(Robot bot, int size)
    {
        bot.SpeedTo(200);
        Vector right = new(1, 0, 0), left = new(-1, 0, 0);
        for (int i = 0; i < size; i++)
        {
            bot.Move((i & 1) == 0 ? right : left);
        }
        // Generous: 1 ms per action plus a minute, so a stalled link fails the scenario instead of hanging the harness.
        using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(1) + TimeSpan.FromMilliseconds(size));
        bot.WaitForCompletionAsync(timeout.Token).GetAwaiter().GetResult();
    }

    public override void Cleanup()
    {
        _bot?.DisconnectAsync().GetAwaiter().GetResult();
        _twin?.DisposeAsync().AsTask().GetAwaiter().GetResult();
        _bot = null;
        _twin = null;
    }
}

using Machina.Cli.Programs;
using Machina.Cli.Simulation;
using Machina.Cli.Terminal;

namespace Machina.Cli.Commands;

/// <summary><c>machina run</c>: streams a program to a controller (or a virtual one) and shows its progress.</summary>
internal static class RunCommand
{
    /// <summary>Most actions issued but not yet executed: the program is read only as fast as the robot works, so memory stays flat.</summary>
    internal const int Window = 500;

    internal static readonly CliCommand Command = new(
        "run",
        "Stream a program to a robot (or a virtual one) and watch it run",
        $"""
        Usage: machina run PROGRAM --brand abb|ur|kuka (--sim | --host H --port P) [options]

        Streams PROGRAM, a text file of Machina instructions (- for standard input), to Machina's driver on the controller
        and shows the progress: a bar with counts, rate and time left on a terminal, plain lines when redirected.
        Once connected, and before the first action is sent, the whole program is read and checked: every statement parsed,
        every action tried as the robot would issue it (what the brand's driver cannot run is refused), and with the arm's
        model (--model, or always with --sim) every target checked for reach and joint limits. The robot moves only if the
        whole program passes. When the controller reports that it could not run an action, the run stops with its line.
        Ctrl+C stops cleanly: nothing more is sent, and the actions already sent to the controller are listed.
        While a program file streams, keys act on the controller at once, even during a move: space pauses the robot
        (the arm holds where it is) and resumes it; s stops it (the move under way stops where the arm is, nothing
        after it runs). Keys are read from standard input: press the key, then Enter. Online pause and stop: UR and ABB.
        Online control in this build: {VirtualControllers.AvailableNames}.

        Options:
          --brand B         the robot brand (abb, ur, kuka)
          --sim             start a virtual controller on this computer and stream to it (no robot needed)
          --host H          the controller's address (where Machina's driver runs), e.g. 192.168.125.1
          --port P          the driver's port (default {SimCommand.DefaultPort})
          --model M         the robot arm model, e.g. "IRB 120": motions are checked and problems printed
          --speed-factor F  with --sim: how much faster than real time the virtual robot moves (default 1)
          --name NAME       the program name (default: the file name)

        SAFETY: a real robot moves. Try the program with --sim first, run it at reduced speed, keep clear of the
        working area and keep the emergency stop in reach.

        Examples:
          machina run square.machina --brand abb --sim
          machina run square.machina --brand abb --host 192.168.125.1 --port 7000
        """,
        Options: ["--brand", "--host", "--port", "--model", "--speed-factor", "--name"],
        Flags: ["--sim"],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (or - for standard input)");
        RobotType brand = Brands.Parse(args.Required("--brand", "(abb, ur or kuka)"), Brands.All);
        if (!Brands.IsArm(brand))
        {
            throw new UsageException($"{brand} programs cannot be streamed: only robot arms (abb, ur, kuka) are controlled online. Compile it: machina compile {path} --brand {Brands.Name(brand)}");
        }
        bool sim = args.Has("--sim");
        string? host = args.Value("--host");
        if (sim == (host is not null))
        {
            throw new UsageException("machina run needs either --sim (a virtual controller on this computer) or --host H --port P (a real controller), not " +
                (sim ? "both." : "none of them.") + " See: machina run --help");
        }
        if (sim && args.HasValue("--port"))
        {
            throw new UsageException("--port goes with --host; with --sim the virtual controller picks a free port.");
        }
        if (!sim && args.HasValue("--speed-factor"))
        {
            throw new UsageException("--speed-factor is for the virtual controller (--sim); a real robot moves at the programmed speed.");
        }
        int port = args.Port("--port", SimCommand.DefaultPort);
        RobotModel? model = Brands.Model(args.Value("--model"), brand);
        if (sim && model is null)
        {
            model = RunCheck.VirtualModel(brand); // the virtual controller moves like this arm: check against it
        }
        double speed = args.Positive("--speed-factor", 1);
        string? name = args.Value("--name");

        if (path != "-")
        {
            // Every statement is parsed before anything is started: a malformed line stops the run before it connects.
            using ProgramReader parse = ProgramReader.Open(path, context, name);
            _ = parse.Read(context.Cancellation).LongCount();
        }
        if (!VirtualControllers.Available.Contains(brand))
        {
            throw VirtualControllers.NotInThisBuild(brand);
        }
        await using RunningController? controller = sim
            ? await VirtualControllers.StartAsync(brand, new VirtualControllerOptions(speed, model), context.Cancellation).ConfigureAwait(false)
            : null;
        using ProgramReader reader = ProgramReader.Open(path, context, name);
        // Standard input can be read only once: it is checked as it streams, and stops at its first problem.
        ProgramReader? check = path == "-" ? null : ProgramReader.Open(path, context, name);
        try
        {
            var run = new Streamer(reader, check, brand, model, context);
            return await run.RunAsync(controller?.Host ?? host!, controller?.Port ?? port).ConfigureAwait(false);
        }
        finally
        {
            check?.Dispose();
        }
    }

    /// <summary>One streamed run: the robot, its events and the counts.</summary>
    private sealed class Streamer(ProgramReader reader, ProgramReader? check, RobotType brand, RobotModel? model, CliContext context)
    {
        private readonly TaskCompletionSource<MachinaException> _lost = new(TaskCreationOptions.RunContinuationsAsynchronously);
        private readonly TaskCompletionSource<CliException> _failed = new(TaskCreationOptions.RunContinuationsAsynchronously);
        private readonly Dictionary<RobotAction, InstructionStatement> _lines = new(ReferenceEqualityComparer.Instance);
        private readonly Lock _gate = new();
        private ProgressReporter _progress = new(context, null);
        private long? _total;
        private long _executed;
        private int _issuingThread;
        private volatile bool _userStop;
        private RunKeys? _keys;
        private InstructionStatement _issuing;

        internal async Task<int> RunAsync(string host, int port)
        {
            Robot robot = model is null ? Robot.Create(reader.ProgramName, brand) : Robot.Create(reader.ProgramName, brand, model);
            robot.Logger.Level = LogLevel.WARNING;
            robot.Logger.Logged += (_, e) => OnLog(e);
            try
            {
                robot.ControlMode(ControlType.Online);
            }
            catch (NotSupportedException)
            {
                throw VirtualControllers.NotInThisBuild(brand);
            }
            robot.ActionExecuted += (_, e) => OnExecuted(e);
            robot.ConnectionLost += (_, e) => _lost.TrySetResult(e.Error);
            robot.ActionFailed += (_, e) => OnFailed(e);
            await context.Stdout.WriteLineAsync($"Connecting to the {brand} controller at {host}:{port}...").ConfigureAwait(false);
            await robot.ConnectAsync(host, port, context.Cancellation).ConfigureAwait(false);
            if (check is not null)
            {
                try
                {
                    _total = RunCheck.Check(robot, check, context);
                }
                catch
                {
                    await robot.DisconnectAsync().ConfigureAwait(false);
                    throw;
                }
                _progress = new ProgressReporter(context, _total);
            }
            await context.Stdout.WriteLineAsync($"Connected. The robot is at {robot.GetCurrentPosition()?.ToString() ?? "an unknown position"}, " +
                $"axes {robot.GetCurrentAxes()?.ToString() ?? "unknown"}. " + (_total is long t ? $"{reader.DisplayName} checked: {t} action{(t == 1 ? "" : "s")}" +
                (model is null ? "" : $", every target within the {model.Name}'s reach and limits") + ". Streaming it..." : $"Streaming {reader.DisplayName}...")).ConfigureAwait(false);
            long issued = 0;
            RunKeys? keys = null;
            if (check is not null)
            {
                // The program comes from a file, so standard input is free for keys.
                keys = _keys = RunKeys.Start(robot, context, () => _userStop = true);
                await context.Stdout.WriteLineAsync(RunKeys.Help).ConfigureAwait(false);
            }
            try
            {
                foreach (InstructionStatement statement in reader.Read(context.Cancellation))
                {
                    await WaitForRoomAsync(robot).ConfigureAwait(false);
                    Issue(robot, statement);
                    issued++;
                }
                try
                {
                    await WhilePausedAsync(async () =>
                    {
                        Task done = robot.WaitForCompletionAsync(context.Cancellation);
                        await Task.WhenAny(done, _lost.Task, _failed.Task).ConfigureAwait(false);
                        ThrowIfLost();
                        await done.ConfigureAwait(false);
                    }).ConfigureAwait(false);
                }
                catch (ActionFailedException failure)
                {
                    throw _userStop && failure.ControllerCode == "stopped" ? StoppedByUser(failure.Action) : FailedError(failure);
                }
                _progress.Update(Interlocked.Read(ref _executed), 0);
                _progress.Finish();
                RobotState final = robot.GetExecutedState();
                await context.Stdout.WriteLineAsync($"Done: {Counted.Of(Interlocked.Read(ref _executed), "action")} executed. The robot is at " +
                    $"{final.Position?.ToString() ?? "an unknown position"}, axes {final.Axes?.ToString() ?? "unknown"}.").ConfigureAwait(false);
                await robot.DisconnectAsync().ConfigureAwait(false);
                return ExitCodes.Ok;
            }
            catch (Exception ex) when (ex is OperationCanceledException or CliException or MachinaException)
            {
                _progress.Finish();
                int cancelled = robot.ClearPendingActions();
                IReadOnlyList<RobotAction> sent = robot.GetPendingActions();
                robot.Logger.Level = LogLevel.ERROR;   // the line below says what was left; the library's own warning would repeat it
                await robot.DisconnectAsync().ConfigureAwait(false);
                string why = ex is OperationCanceledException ? "Stopped (Ctrl+C)" : "Stopped";
                long executed = Interlocked.Read(ref _executed);
                long of = _total is long all ? all : issued;
                await context.Stderr.WriteLineAsync($"{why} after {executed} of {Counted.Of(of, "action")} {(of == 1 ? "was" : "were")} executed " +
                    $"({issued} issued); {cancelled} not sent yet {(cancelled == 1 ? "was" : "were")} cancelled." + (sent.Count > 0
                        ? $" {sent.Count} {(sent.Count == 1 ? "was" : "were")} sent and the controller may still run {(sent.Count == 1 ? "it" : "them")} (first: {sent[0].ToInstruction()})."
                        : "")).ConfigureAwait(false);
                throw;
            }
            finally
            {
                keys?.Finish();
            }
        }

        private void Issue(Robot robot, InstructionStatement statement)
        {
            lock (_gate)
            {
                _issuingThread = Environment.CurrentManagedThreadId;
                _issuing = statement;
                // Known before issuing, so that even an action executed at once finds its line; a freshly read action is issued as itself.
                _lines[statement.Action] = statement;
            }
            try
            {
                robot.Issue(statement.Action);
            }
            catch (ActionRefusedException ex)
            {
                lock (_gate)
                {
                    _lines.Remove(statement.Action);
                }
                throw CliException.At(reader.DisplayName, statement.Line, statement.Column, $"{statement.Action.ToInstruction()} cannot be applied: {ex.Reason}");
            }
            finally
            {
                lock (_gate)
                {
                    _issuingThread = 0;
                }
            }
        }

        /// <summary>Waits until fewer than <see cref="Window"/> actions are pending (the library's back-pressure); a failure or a lost link stops the run.</summary>
        private async Task WaitForRoomAsync(Robot robot)
        {
            ThrowIfLost();
            try
            {
                await WhilePausedAsync(() => robot.WaitForRoomAsync(Window, context.Cancellation)).ConfigureAwait(false);
            }
            catch (ActionFailedException failure)
            {
                throw FailedError(failure);
            }
            catch (RobotConnectionException lost)
            {
                throw _userStop ? StoppedByUser() : new CliException($"The connection to the controller was lost: {lost.Message}");
            }
        }

        /// <summary>The run's error for an action the controller could not run, at the action's line when it is known.</summary>
        private CliException FailedError(ActionFailedException failure)
        {
            InstructionStatement statement;
            bool known;
            lock (_gate)
            {
                known = _lines.TryGetValue(failure.Action, out statement);
            }
            return RunCommand.FailedError(reader.DisplayName, known ? statement : null, failure);
        }

        /// <summary>Runs a wait again after a pause (space): a paused robot fails waits at once, which is no reason to end the run.</summary>
        private async Task WhilePausedAsync(Func<Task> wait)
        {
            while (true)
            {
                Task changed = _keys?.Changed ?? Task.CompletedTask;
                try
                {
                    await wait().ConfigureAwait(false);
                    return;
                }
                catch (RobotStoppedException) when (_keys is { IsPaused: true })
                {
                    await Task.WhenAny(changed, _lost.Task, _failed.Task).WaitAsync(context.Cancellation).ConfigureAwait(false);
                    ThrowIfLost();
                }
            }
        }

        private void ThrowIfLost()
        {
            if (_failed.Task.IsCompletedSuccessfully)
            {
                throw _failed.Task.Result;
            }
            if (_lost.Task.IsCompletedSuccessfully)
            {
                throw _userStop ? StoppedByUser() : new CliException($"The connection to the controller was lost: {_lost.Task.Result.Message}");
            }
        }

        private void OnExecuted(ActionExecutedArgs e)
        {
            long executed = Interlocked.Increment(ref _executed);
            InstructionStatement statement;
            lock (_gate)
            {
                _lines.Remove(e.LastAction, out statement);
            }
            _progress.Update(executed, statement.Line);
        }

        /// <summary>The controller could not run an action and stopped: the run stops with the action's line and the controller's reason.</summary>
        private void OnFailed(ActionFailedArgs e) => _failed.TrySetResult(_userStop && e.Failure.ControllerCode == "stopped"
            ? StoppedByUser(e.Action)
            : FailedError(e.Failure));

        /// <summary>The run's end after the s key: where the stopped action was, when one was under way.</summary>
        private CliException StoppedByUser(RobotAction? action = null)
        {
            InstructionStatement statement = default;
            bool known = false;
            if (action is not null)
            {
                lock (_gate)
                {
                    known = _lines.TryGetValue(action, out statement);
                }
            }
            string problem = action is null
                ? "stopped by the user (s); nothing was running."
                : $"stopped by the user (s): {action.ToInstruction()} stopped where the arm was and nothing after it ran.";
            return known ? CliException.At(reader.DisplayName, statement.Line, statement.Column, problem) : new CliException($"{reader.DisplayName}: {problem}");
        }

        private void OnLog(LogEntry entry)
        {
            string where = "";
            lock (_gate)
            {
                if (_issuingThread == Environment.CurrentManagedThreadId)
                {
                    where = $"{reader.DisplayName}:{_issuing.Line}:{_issuing.Column}: ";
                }
            }
            // A refused action is reported once, as the error that stops the run.
            if (entry.Refused is not null)
            {
                return;
            }
            context.Stderr.WriteLine($"{where}{(entry.Level == LogLevel.ERROR ? "error" : "warning")}: {PrintableText.Of(entry.Message, keepLines: true)}");
        }
    }

    /// <summary>The error for an action the controller could not run: its line (when known) and the controller's reason and code.</summary>
    internal static CliException FailedError(string file, InstructionStatement? statement, ActionFailedException e)
    {
        string problem = $"the controller could not run {e.Action.ToInstruction()} and stopped: {e.ControllerReason}" +
            (e.ControllerCode is string code ? $" (error {code})" : "") + ".";
        return statement is InstructionStatement s
            ? CliException.At(file, s.Line, s.Column, problem)
            : new CliException($"{file}: {problem}");
    }
}

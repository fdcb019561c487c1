namespace Machina.Cli.Terminal;

/// <summary>
/// The keys of <c>machina run</c> while a program file streams: space pauses the robot on the controller or resumes it, s stops
/// it (Robot.Pause / Resume / Stop, out of band: a move under way holds or stops where the arm is). Keys are read from standard
/// input, a character each (line ends are ignored): on a terminal a key acts once Enter is pressed.
/// </summary>
internal sealed class RunKeys
{
    /// <summary>Pauses a running robot, resumes a paused one.</summary>
    internal const char PauseResume = ' ';

    /// <summary>Stops the robot: the move under way stops where the arm is and nothing after it runs.</summary>
    internal const char Stop = 's';

    private readonly Robot _robot;
    private readonly CliContext _context;
    private readonly Action _stopping;
    private readonly Lock _gate = new();
    private volatile bool _done;
    private bool _paused;
    private TaskCompletionSource _changed = new(TaskCreationOptions.RunContinuationsAsynchronously);

    private RunKeys(Robot robot, CliContext context, Action stopping)
    {
        _robot = robot;
        _context = context;
        _stopping = stopping;
    }

    /// <summary>The line that tells the user which keys there are.</summary>
    internal static string Help => "Keys (then Enter): space pauses or resumes the robot, s stops it.";

    /// <summary>
    /// Reads keys for <paramref name="robot"/> on a thread of its own until input ends or <see cref="Finish"/>;
    /// <paramref name="stopping"/> is called before the robot is asked to stop.
    /// </summary>
    internal static RunKeys Start(Robot robot, CliContext context, Action stopping)
    {
        var keys = new RunKeys(robot, context, stopping);
        var thread = new Thread(keys.Read) { IsBackground = true, Name = "machina run keys" };
        thread.Start();
        return keys;
    }

    /// <summary>True from the moment a pause is asked for until the robot resumed (or the pause failed).</summary>
    internal bool IsPaused
    {
        get
        {
            lock (_gate)
            {
                return _paused;
            }
        }
    }

    /// <summary>Completes at the next change: a resume, a failed pause, or a stop. Take it before the wait it should end.</summary>
    internal Task Changed
    {
        get
        {
            lock (_gate)
            {
                return _changed.Task;
            }
        }
    }

    private void SetPaused(bool paused)
    {
        TaskCompletionSource changed;
        lock (_gate)
        {
            _paused = paused;
            changed = _changed;
            _changed = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
        }
        changed.TrySetResult();
    }

    /// <summary>The run is over: keys read from now on do nothing.</summary>
    internal void Finish() => _done = true;

    private void Read()
    {
        while (!_done)
        {
            int key;
            try
            {
                key = _context.Stdin.Read();
            }
            catch (Exception ex) when (ex is IOException or InvalidOperationException or ObjectDisposedException)
            {
                return; // no input to read keys from
            }
            if (key < 0)
            {
                return;
            }
            if (!_done)
            {
                // One at a time and in order: a stop typed after a pause acts after the pause did.
                Act(char.ToLowerInvariant((char)key)).GetAwaiter().GetResult();
            }
        }
    }

    private async Task Act(char key)
    {
        try
        {
            switch (key)
            {
                case PauseResume when IsPaused:
                    await _robot.ResumeAsync(_context.Cancellation).ConfigureAwait(false);
                    await _context.Stdout.WriteLineAsync("Resumed.").ConfigureAwait(false);
                    SetPaused(false);
                    break;
                case PauseResume:
                    // Paused before it is asked: the run's waits fail as soon as the robot holds, and must know why.
                    SetPaused(true);
                    try
                    {
                        await _robot.PauseAsync(_context.Cancellation).ConfigureAwait(false);
                    }
                    catch
                    {
                        SetPaused(false);
                        throw;
                    }
                    await _context.Stdout.WriteLineAsync("Paused: the arm holds where it is. Press space to resume, s to stop.").ConfigureAwait(false);
                    break;
                case Stop:
                    _stopping();
                    await _context.Stdout.WriteLineAsync("Stopping the robot (s)...").ConfigureAwait(false);
                    try
                    {
                        await _robot.StopAsync(_context.Cancellation).ConfigureAwait(false);
                    }
                    finally
                    {
                        SetPaused(false);
                    }
                    break;
            }
        }
        catch (Exception ex) when (ex is MachinaException or NotSupportedException or InvalidOperationException or OperationCanceledException)
        {
            _context.Warn($"the key '{(key == ' ' ? "space" : key.ToString())}' did nothing: {ex.Message}");
        }
    }
}

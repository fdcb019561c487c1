using System.Threading.Channels;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// Program selection on the robot interpreter, as KUKA's program management does it: a controller can stand with no program
/// selected ($PRO_STATE1 #P_FREE), and the commands another interpreter writes to the command channel
/// (<c>CWRITE($CMD, STAT, MODE, "RUN /R1/NAME()")</c>, <c>"STOP 1"</c>, <c>"RESET 1"</c>, <c>"CANCEL 1"</c>) select and start, stop,
/// reset and deselect the robot program. A RUN is started by whoever serves the robot interpreter
/// (<see cref="RunNextSelected"/>); a command the program's state does not allow answers #CMD_ABORT, with why in the logbook.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>One item per RUN, for the robot interpreter to look at <see cref="_pendingRun"/>.</summary>
    private readonly Channel<bool> _runs = System.Threading.Channels.Channel.CreateUnbounded<bool>(new UnboundedChannelOptions { SingleReader = true });

    /// <summary>The program a RUN selected and the robot interpreter has not started yet (under the gate); null: none.</summary>
    private string? _pendingRun;

    /// <summary>Stops the program <see cref="RunNextSelected"/> runs (a STOP command); null while none runs so.</summary>
    private CancellationTokenSource? _stopRun;

    /// <summary>
    /// Selects <paramref name="routine"/> as the robot program (the main routine <see cref="Run"/> runs), or none when null
    /// ($PRO_STATE1 #P_FREE); false when no program (a routine without parameters) of that name is loaded.
    /// </summary>
    public bool Select(string? routine)
    {
        if (routine is not null && !IsProgram(routine))
        {
            return false;
        }
        lock (_gate)
        {
            MainRoutine = routine;
            _pendingRun = null;
        }
        ProgramStatus.Set(KrlProgramState.Idle, null);
        return true;
    }

    /// <summary>
    /// Waits for a RUN command, then runs the program it selected as <see cref="Run"/> does (a STOP command stops it); null
    /// when <paramref name="cancellation"/> ends the wait first.
    /// </summary>
    public KrlProgramState? RunNextSelected(CancellationToken cancellation)
    {
        string? routine;
        do
        {
            try
            {
                TwinWait.For(_runs.Reader.ReadAsync(cancellation).AsTask(), cancellation);
            }
            catch (OperationCanceledException)
            {
                return null;
            }
            lock (_gate)
            {
                (routine, _pendingRun) = (_pendingRun, null);
            }
        }
        while (routine is null); // a CANCEL came before the interpreter started it, or one start answered two RUNs
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellation);
        Volatile.Write(ref _stopRun, stop);
        try
        {
            return Run(routine, stop.Token);
        }
        finally
        {
            Volatile.Write(ref _stopRun, null);
        }
    }

    /// <summary>
    /// Carries out a program-management command of the command channel: "RUN /R1/NAME()" (with no program selected: selects NAME
    /// and asks the robot interpreter to start it), "STOP 1" (stops the running program), "RESET 1" (a selected program that
    /// does not run: back to its start, #P_RESET) and "CANCEL 1" (deselects a program that does not run: #P_FREE). Returns the
    /// state's RET1 (CMD_OK, or CMD_ABORT with why in the logbook); null for a command the twin does not know.
    /// </summary>
    internal string? Command(string text)
    {
        string command = text.Trim();
        int space = command.IndexOfAny([' ', '/']);
        string verb = (space < 0 ? command : command[..space]).ToUpperInvariant();
        string rest = space < 0 ? "" : command[space..].Trim();
        string state = RobotProgramState;
        return verb switch
        {
            "RUN" => RunCommand(text, ProgramName(rest), state),
            "STOP" => StopCommand(),
            "RESET" when state is "P_ACTIVE" or "P_FREE" => Abort(text, state),
            "RESET" => Reset(),
            "CANCEL" when state is "P_ACTIVE" => Abort(text, state),
            "CANCEL" => Select(null) ? "CMD_OK" : "CMD_ABORT",
            _ => null,
        };
    }

    private string RunCommand(string text, string name, string state)
    {
        if (state != "P_FREE")
        {
            return Abort(text, state);
        }
        if (!Select(name))
        {
            Pendant.Log($"CWRITE($CMD, …, \"{text.Trim()}\"): program {name} not found: no program without parameters of that name is loaded");
            return "CMD_ABORT";
        }
        lock (_gate)
        {
            _pendingRun = name;
        }
        _runs.Writer.TryWrite(true);
        return "CMD_OK";
    }

    private string StopCommand()
    {
        Volatile.Read(ref _stopRun)?.Cancel();
        return "CMD_OK";
    }

    private string Reset()
    {
        ProgramStatus.Set(KrlProgramState.Idle, null);
        return "CMD_OK";
    }

    private string Abort(string text, string state)
    {
        Pendant.Log($"CWRITE($CMD, …, \"{text.Trim()}\") refused: the robot interpreter's program is #{state}");
        return "CMD_ABORT";
    }

    /// <summary>NAME of "/R1/NAME()", "/R1/NAME(1, 2)" or "NAME()": the program's name without its path and arguments.</summary>
    private static string ProgramName(string path)
    {
        int open = path.IndexOf('(', StringComparison.Ordinal);
        string name = (open < 0 ? path : path[..open]).Trim();
        return name[(name.LastIndexOf('/') + 1)..].Trim();
    }

    /// <summary>True when a routine without parameters and without a return value (a program) of that name is loaded.</summary>
    private bool IsProgram(string name) =>
        KrlBinder.FindRoutine(_modules, null, name) is { Parameters.Count: 0, ReturnType: null };
}

using System.Globalization;
using Machina.Simulation.Rapid;
using static Machina.Simulation.Rws.RwsXhtmlWriter;

namespace Machina.Simulation.Rws;

/// <summary>The RAPID resources of the twin's Robot Web Services: execution (start, stop, program pointer), module load and data.</summary>
internal sealed partial class RwsTwinServer
{
    private RwsResponse Execution(string action, IReadOnlyDictionary<string, string> form, string session)
    {
        switch (action)
        {
            case "setcycle":
                if (!HoldsMastership(session))
                {
                    return Error(400, "Bad Request", MastershipRequiredCode, $"Setting the execution cycle needs RAPID mastership{HolderText()}.");
                }
                Twin.Cycle = CycleOf(form.GetValueOrDefault("cycle"), asIs: false);
                return RwsResponse.NoContent();
            case "resetpp":
                if (Twin.IsRunning)
                {
                    return Error(400, "Bad Request", null, "The program pointer cannot be reset while RAPID is running; stop it first.");
                }
                foreach (string task in Twin.TaskNames)
                {
                    Log(10002, $"The program pointer of task {task} has been reset.");
                }
                return RwsResponse.NoContent();
            case "start":
                if (!OperationMode.Equals("AUTO", StringComparison.OrdinalIgnoreCase))
                {
                    return Error(400, "Bad Request", null,
                        $"Start refused: the controller is in manual mode ({OperationMode}); a remote client can start RAPID only in automatic mode.");
                }
                if (!MotorsOn)
                {
                    return Error(400, "Bad Request", null, "Start refused: the motors are off.");
                }
                if (HeldByOther(session) is { } holder)
                {
                    return Error(403, "Forbidden", null, $"Start refused: mastership is held by {holder}.");
                }
                if (Twin.IsRunning)
                {
                    return Error(400, "Bad Request", null, "Start refused: RAPID is already running.");
                }
                Twin.Cycle = CycleOf(form.GetValueOrDefault("cycle"), asIs: true);
                Twin.RestartTasks();
                return RwsResponse.NoContent();
            case "stop":
                Twin.StopTasks(TimeSpan.FromSeconds(10));
                return RwsResponse.NoContent();
            default:
                return Error(400, "Bad Request", null, $"Unknown RAPID execution action \"{action}\".");
        }
    }

    /// <summary>
    /// The run mode a start's or setcycle's <c>cycle</c> field asks for: forever (continuous), once (single cycle), or, for a start, asis
    /// (and no field): the mode the controller has.
    /// </summary>
    private RapidExecutionCycle CycleOf(string? cycle, bool asIs) => cycle switch
    {
        "forever" => RapidExecutionCycle.Forever,
        "once" => RapidExecutionCycle.Once,
        "asis" or null when asIs => Twin.Cycle,
        _ => throw new FormatException($"The cycle must be {(asIs ? "forever, once or asis" : "once or forever")}, not \"{PrintableText.Of(cycle ?? "")}\"."),
    };

    /// <summary>The execution cycle as RWS names it.</summary>
    private string CycleText => Twin.Cycle == RapidExecutionCycle.Forever ? "forever" : "once";

    private RwsResponse LoadModule(string task, IReadOnlyDictionary<string, string> form, string session)
    {
        if (!HoldsMastership(session))
        {
            return Error(400, "Bad Request", MastershipRequiredCode, $"Loading a module needs RAPID mastership{HolderText()}.");
        }
        if (Twin.IsRunning || (Twin.TaskNames.Contains(task, StringComparer.OrdinalIgnoreCase) && Twin.Task(task).State == RapidProgramState.Running))
        {
            return Error(400, "Bad Request", null, $"A module cannot be loaded while RAPID is running ({task} runs); stop it first.");
        }
        string path = form["modulepath"];
        string? text = ReadModuleFile(path);
        if (text is null)
        {
            return Error(400, "Bad Request", null, $"The file {path} does not exist on the controller.");
        }
        try
        {
            Twin.LoadModuleFile(task, path[(path.LastIndexOf('/') + 1)..], text, form.GetValueOrDefault("replace") == "true");
            return RwsResponse.NoContent();
        }
        catch (RapidLoadException ex)
        {
            string message = $"{ex.Module ?? path}: {ex.Message}";
            Log(0, message);
            return Error(400, "Bad Request", null, message);
        }
    }

    /// <summary>A RAPID value as RWS writes it: a string in quotes, anything else as RAPID writes it.</summary>
    private static string DataText(object value) => value is string t ? $"\"{t}\"" : RapidValues.ToText(value);

    private RwsResponse Symbol(string task, string module, string symbol, bool get, IReadOnlyDictionary<string, string> form, string session)
    {
        RapidCell? cell = Twin.FindData(task, module, symbol);
        if (cell is null)
        {
            return Error(400, "Bad Request", null, $"The task {task} has no global data {module}/{symbol}.");
        }
        if (get)
        {
            // The task writes records and arrays in place on its own thread: the text is of one state of the value, read again
            // while the task writes it meanwhile (the controller answers with the value between two writes too).
            string? read = cell.Read(DataText);
            return read is null
                ? Error(503, "Service Unavailable", null, $"{symbol} was written during each attempt to read it; try again.")
                : State("rapid", Item("rap-data", $"RAPID/{task}/{module}/{symbol}", ("value", read)));
        }
        if (!HoldsMastership(session))
        {
            return Error(400, "Bad Request", MastershipRequiredCode, $"Updating RAPID data needs RAPID mastership{HolderText()}.");
        }
        if (cell.Storage == RapidStorage.Const)
        {
            return Error(400, "Bad Request", null, $"{symbol} is a CONST and cannot be changed.");
        }
        string text = form["value"].Trim();
        cell.Value = cell.Value switch
        {
            double => double.Parse(text, NumberStyles.Float, CultureInfo.InvariantCulture),
            bool => text.ToUpperInvariant() switch { "TRUE" => true, "FALSE" => false, _ => throw new FormatException($"\"{text}\" is not TRUE or FALSE.") },
            string => text.Length >= 2 && text[0] == '"' && text[^1] == '"' ? text[1..^1] : throw new FormatException($"{text} is not a quoted string."),
            _ => throw new FormatException($"The twin sets only num, bool and string data through RWS, not {symbol}."),
        };
        Twin.PersistentWritten();
        return RwsResponse.NoContent();
    }
}

namespace Machina.Simulation.Rapid;

/// <summary>Where a task's program is.</summary>
internal enum RapidProgramState
{
    /// <summary>Loaded, not started.</summary>
    Ready,

    /// <summary>Running.</summary>
    Running,

    /// <summary>Main returned, or the program ran EXIT.</summary>
    Finished,

    /// <summary>The program ran Stop.</summary>
    Stopped,

    /// <summary>An error no handler took stopped the task (see the error message).</summary>
    Failed,
}

/// <summary>
/// A RAPID task of the twin controller (e.g. T_ROB1): its loaded modules, their data, the machine that runs them and the motion
/// settings that instructions such as VelSet, AccSet and ConfL change.
/// </summary>
internal sealed partial class RapidTask
{
    private int _ticks;

    /// <summary>A task named <paramref name="name"/> of <paramref name="controller"/>.</summary>
    public RapidTask(RapidTwinController controller, string name)
    {
        Controller = controller;
        Name = name;
        Machine = new RapidMachine(this);
        RapidPredefined.AddTo(Program, controller);
    }

    /// <summary>The task's name.</summary>
    public string Name { get; }

    /// <summary>The controller.</summary>
    public RapidTwinController Controller { get; }

    /// <summary>The bound modules and their data.</summary>
    public RapidProgram Program { get; } = new();

    /// <summary>The machine that runs the statements.</summary>
    public RapidMachine Machine { get; }

    /// <summary>Cancels the running program (the controller's stop).</summary>
    public CancellationToken CancellationToken { get; set; }

    /// <summary>The active work object's frame (from the last motion instruction).</summary>
    public Pose WorkObject { get; set; } = Pose.Identity;

    /// <summary>VelSet: the speed override in percent.</summary>
    public double SpeedOverride { get; set; } = 100;

    /// <summary>VelSet: the largest TCP speed, mm/s.</summary>
    public double MaxSpeed { get; set; } = 5000;

    /// <summary>AccSet: the acceleration in percent of the maximum.</summary>
    public double AccelerationPercent { get; set; } = 100;

    /// <summary>WorldAccLim: the TCP acceleration limit in m/s² (null: the model's own).</summary>
    public double? AccelerationLimit { get; set; }

    /// <summary>ConfL \On: linear moves keep the target's axis configuration.</summary>
    public bool ConfL { get; set; } = true;

    /// <summary>ConfJ \On: joint moves go to the target's axis configuration.</summary>
    public bool ConfJ { get; set; } = true;

    /// <summary>SingArea \Wrist: the wrist may deviate near singularities.</summary>
    public bool SingAreaWrist { get; set; }

    /// <summary>Loads and binds <paramref name="modules"/> (name, text); throws <see cref="RapidLoadException"/> for the first mistake.</summary>
    public void Load(IEnumerable<(string Name, string Text)> modules)
    {
        var parsed = new List<RapidModule>();
        var files = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        foreach ((string name, string text) in modules)
        {
            try
            {
                RapidModule module = RapidParser.Parse(text, Controller.Options.Limits);
                files[module.Name] = name;
                parsed.Add(module);
            }
            catch (RapidLoadException ex)
            {
                throw new RapidLoadException(ex.Line, ex.Reason) { Module = name };
            }
        }
        try
        {
            RapidBinder.Bind(Program, Machine, parsed, Controller.Builtins, Controller.Persistents);
        }
        catch (RapidLoadException ex)
        {
            throw new RapidLoadException(ex.Line, ex.Reason) { Module = ex.Module is null ? null : files.GetValueOrDefault(ex.Module, ex.Module) };
        }
    }

    /// <summary>Checks for a stop every so many loop turns (a program in an endless loop can still be stopped).</summary>
    public void Tick()
    {
        if (++_ticks % 256 == 0)
        {
            CancellationToken.ThrowIfCancellationRequested();
        }
    }
}

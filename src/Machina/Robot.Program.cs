namespace Machina;

public sealed partial class Robot
{
    private RobotCursor? _programStart;

    /// <summary>
    /// Reads one or more instructions, e.g. <c>"MoveTo(400,300,500); Wait(1000);"</c>, and issues them in order. Either all
    /// of them are issued or, if any is malformed or cannot be applied, none is.
    /// </summary>
    /// <returns>True (kept for programs written for the original Machina).</returns>
    /// <exception cref="InstructionParseException">The text is malformed.</exception>
    /// <exception cref="ActionRefusedException">An instruction cannot be applied to the robot's state.</exception>
    public bool Do(string instructions)
    {
        IReadOnlyList<RobotAction> actions = Instructions.Parse(instructions ?? throw new ArgumentNullException(nameof(instructions)));
        IssueAll(actions);
        return true;
    }

    /// <summary>Checks that every action would apply in sequence, on a copy of the state, so that a later failure issues nothing. The caller holds the lock.</summary>
    private void DryRun(IReadOnlyList<RobotAction> actions)
    {
        var trial = new RobotCursor();
        trial.CopyFrom(_issueCursor);
        trial.Strict = _issueCursor.Strict;
        foreach (RobotAction action in actions)
        {
            if ((_session?.WhyCannotStream(action) ?? trial.TryApply(action) ?? _session?.WhyCannotSend(action, trial)) is string refusal)
            {
                throw new ActionRefusedException(action, refusal);
            }
        }
    }

    /// <summary>Compiles every action issued so far (offline) into a program in this robot's language. Compiling does not change the robot: compiling twice gives the same program.</summary>
    /// <param name="inlineTargets">Write targets inside motion instructions (true) or as declared variables (false).</param>
    /// <param name="humanComments">Add a description of each action as a comment.</param>
    public RobotProgram Compile(bool inlineTargets = true, bool humanComments = true) =>
        Compile(Brand, new CompileOptions { InlineTargets = inlineTargets, HumanComments = humanComments });

    /// <summary>Compiles every action issued so far into a program in <paramref name="language"/> (any brand, not only this robot's).</summary>
    public RobotProgram Compile(RobotType language, CompileOptions? options = null) =>
        Compilers.For(EnumText.RequireDefined(language, nameof(language))).Compile(CreateCompileJob(options));

    /// <summary>
    /// Compiles straight into files in <paramref name="folderPath"/> without building the program text in memory (for very long
    /// toolpaths). Uses this robot's language unless <paramref name="language"/> is given. Returns the paths written.
    /// </summary>
    public IReadOnlyList<string> CompileToFolder(string folderPath, RobotType? language = null, CompileOptions? options = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(folderPath);
        return Compilers.For(EnumText.RequireDefined(language ?? Brand, nameof(language))).CompileToFolder(CreateCompileJob(options), folderPath);
    }

    private CompileJob CreateCompileJob(CompileOptions? options)
    {
        if (_session is { } session)
        {
            throw new InvalidOperationException(session.IsConnected
                ? "Compile works in offline mode; this robot is streaming its actions to a controller."
                : "Compile works in offline mode; this robot is in online mode (not connected), so its actions wait to be streamed. "
                  + "Call ControlMode(\"offline\") first to compile the actions issued from then on.");
        }
        RobotProgramSnapshot actions;
        RobotCursor start = new();
        RobotModel? model;
        lock (_issueLock)
        {
            model = _issueCursor.Model;
            actions = _programActions.Snapshot();
            if (_programStart is not null)
            {
                start.CopyFrom(_programStart);
            }
        }
        return new CompileJob(CompileJob.SafeProgramName(Name), actions, options ?? CompileOptions.Default, () =>
        {
            var cursor = new RobotCursor();
            cursor.CopyFrom(start);
            return cursor;
        }) { Model = model };
    }

    /// <summary>The actions issued so far that the next <c>Compile()</c> will contain.</summary>
    public IReadOnlyList<RobotAction> GetProgramActions()
    {
        lock (_issueLock)
        {
            return Array.AsReadOnly(_programActions.ToArray());
        }
    }

    /// <summary>Starts a new program: the actions issued so far are forgotten, and the next program starts from the current state.</summary>
    public void ClearProgram()
    {
        lock (_issueLock)
        {
            _programStart ??= new RobotCursor();
            _programStart.CopyFrom(_issueCursor);
            _programActions.Clear();
        }
    }

    /// <summary>Saves a compiled program's files into a folder named after the program inside <paramref name="folderPath"/> (e.g. <c>HelloRobot_Program</c>).</summary>
    /// <returns>True (kept for scripts written as <c>if (bot.SaveProgram(...))</c>): a disk error throws, as in <see cref="RobotProgram.SaveToFolder"/>
    /// and <see cref="CompileToFolder"/>.</returns>
    /// <exception cref="ArgumentException"><paramref name="folderPath"/> is null, empty or blank.</exception>
    /// <exception cref="IOException">The disk refused (the folder is a file, the disk is full, …); the error is also logged.</exception>
    /// <exception cref="UnauthorizedAccessException">No permission to write there; the error is also logged.</exception>
    public bool SaveProgram(RobotProgram program, string folderPath)
    {
        ArgumentNullException.ThrowIfNull(program);
        // An empty path would silently write into the process's current directory.
        ArgumentException.ThrowIfNullOrWhiteSpace(folderPath);
        string folder = Path.Combine(folderPath, CompileJob.SafeProgramName(program.Name + "_Program"));
        try
        {
            program.SaveToFolder(folder);
            return true;
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException)
        {
            Logger.Error($"Could not save the program to \"{folder}\": {ex.Message}");
            throw;
        }
    }
}

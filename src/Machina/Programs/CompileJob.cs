using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Everything a compiler needs: the program name, the actions in order, the options, and a place for warnings.</summary>
internal sealed class CompileJob
{
    private readonly List<ProgramWarning> _warnings = [];

    internal CompileJob(string programName, IEnumerable<RobotAction> actions, CompileOptions options, Func<RobotCursor>? newCursor = null)
    {
        ProgramName = programName;
        Actions = actions;
        Options = options;
        _newCursor = newCursor ?? (() => new RobotCursor());
    }

    private readonly Func<RobotCursor> _newCursor;

    /// <summary>Program name, safe for robot languages.</summary>
    internal string ProgramName { get; }

    /// <summary>
    /// The actions, in issue order. Compilers may go over them more than once (a pass to collect declarations, a pass to
    /// write), so this is a list, or a source that reads its text again for each pass (<see cref="InstructionSource"/>).
    /// </summary>
    internal IEnumerable<RobotAction> Actions { get; }

    /// <summary>
    /// Where the actions come from when they are read from instruction text (null for a robot's program): warnings then carry
    /// the line of their action, and an action that cannot be applied stops the compilation with its position.
    /// </summary>
    internal InstructionSource? Source { get; init; }

    /// <summary>Compile options.</summary>
    internal CompileOptions Options { get; }

    private (List<string> Declarations, bool SetsAcceleration, bool ReadsDigital, bool ReadsAnalog)? _survey;

    /// <summary>The statements of the custom-code declarations (<c>CustomCode(..., true)</c>), in order, from one pass over the actions.</summary>
    internal IReadOnlyList<string> CustomDeclarations => Survey().Declarations;

    /// <summary>True when any action sets the acceleration (same pass as <see cref="CustomDeclarations"/>).</summary>
    internal bool SetsAcceleration => Survey().SetsAcceleration;

    /// <summary>True when any action reads a digital input (same pass as <see cref="CustomDeclarations"/>).</summary>
    internal bool ReadsDigital => Survey().ReadsDigital;

    /// <summary>True when any action reads an analog input (same pass as <see cref="CustomDeclarations"/>).</summary>
    internal bool ReadsAnalog => Survey().ReadsAnalog;

    /// <summary>
    /// Text that every statement the survey looks for contains: <c>CustomCode</c>, and <c>Acceleration</c> in both
    /// <c>Acceleration</c> and <c>AccelerationTo</c>, <c>Read</c> in <c>ReadDigital</c> and <c>ReadAnalog</c> (instruction names are case-sensitive).
    /// </summary>
    private static readonly string[] SurveyedInstructions = ["CustomCode", "Acceleration", "Read"];

    private (List<string> Declarations, bool SetsAcceleration, bool ReadsDigital, bool ReadsAnalog) Survey()
    {
        if (_survey is null && Source is not null && !Source.MayContain(SurveyedInstructions))
        {
            // A text that never names the statements the survey looks for has none of them: no pass needed.
            _survey = ([], false, false, false);
        }
        if (_survey is null)
        {
            var declarations = new List<string>();
            bool acceleration = false, digital = false, analog = false;
            foreach (RobotAction action in Actions)
            {
                if (action is ActionCustomCode { IsDeclaration: true } custom)
                {
                    declarations.Add(custom.Statement);
                }
                acceleration |= action is ActionAcceleration;
                digital |= action is ActionReadInput { IsAnalog: false };
                analog |= action is ActionReadInput { IsAnalog: true };
            }
            _survey = (declarations, acceleration, digital, analog);
        }
        return _survey.Value;
    }

    /// <summary>Warnings collected so far.</summary>
    internal IReadOnlyList<ProgramWarning> Warnings => _warnings;

    /// <summary>Records that <paramref name="action"/> could not be expressed exactly.</summary>
    internal void Warn(RobotAction action, string message)
    {
        if (!KeepsMoreWarnings)
        {
            WarningCount++;
            return;
        }
        Keep(new ProgramWarning(action.Id, action.ToInstruction(), message));
    }

    /// <summary>Records a warning whose text is formatted only if it is kept (see <see cref="WarningText"/>).</summary>
    internal void Warn(RobotAction action, [InterpolatedStringHandlerArgument("")] ref WarningText message)
    {
        if (!message.IsWanted)
        {
            WarningCount++;
            return;
        }
        Keep(new ProgramWarning(action.Id, action.ToInstruction(), message.ToStringAndClear()));
    }

    /// <summary>True while warnings are still kept in full (fewer than <see cref="MaxWarningsKept"/> so far).</summary>
    internal bool KeepsMoreWarnings => _warnings.Count < MaxWarningsKept;

    /// <summary>Records a kinematic pre-flight issue of <paramref name="action"/>.</summary>
    internal void Warn(RobotAction action, KinematicIssue issue) =>
        Keep(new ProgramWarning(action.Id, action.ToInstruction(), issue.ToString()) { Kind = issue.Kind });

    /// <summary>Most warnings kept in <see cref="Warnings"/>; later ones are only counted (so that memory does not grow with a long program).</summary>
    internal int MaxWarningsKept { get; init; } = int.MaxValue;

    /// <summary>All warnings raised, including those beyond <see cref="MaxWarningsKept"/>.</summary>
    internal int WarningCount { get; private set; }

    /// <summary>Forgets the warnings and reports of an attempt that is thrown away, so that a new attempt starts afresh.</summary>
    internal void Restart()
    {
        _warnings.Clear();
        WarningCount = 0;
        _kinematicsReported = false;
    }

    private void Keep(ProgramWarning warning)
    {
        WarningCount++;
        if (_warnings.Count < MaxWarningsKept)
        {
            (int Line, int Column)? at = Source?.PositionOf(warning.ActionId);
            _warnings.Add(at is null ? warning : warning with { Line = at.Value.Line, Column = at.Value.Column });
        }
    }

    /// <summary>
    /// For actions read from instruction text, a refusal is an error in the text: it throws with the action's position, as
    /// <c>Robot.Do</c> would refuse it. For a robot's own program (already checked when issued) it returns normally.
    /// </summary>
    private void RefuseFromSource(RobotAction action, string refusal)
    {
        if (Source is not null)
        {
            throw Source.Refused(action, refusal);
        }
    }

    /// <summary>The robot's arm model, or null; with a model the replayed cursors know joints and pose together.</summary>
    internal RobotModel? Model { get; init; }

    private bool _kinematicsReported;

    /// <summary>A cursor in the robot's initial state, to replay the actions on (carrying the model, never strict).</summary>
    internal RobotCursor NewCursor()
    {
        RobotCursor cursor = _newCursor();
        cursor.Model = Model;
        cursor.Strict = false;
        return cursor;
    }

    /// <summary>
    /// Replays every action on a fresh cursor and calls <paramref name="emit"/> with the action and the state after it.
    /// An action the cursor refuses (impossible for actions issued through a robot) is reported as a warning and skipped; the
    /// first replay also reports the kinematic issues and the cursor's own warnings.
    /// </summary>
    // AggressiveOptimization here and on the other per-action methods of a compile (cursor, RAPID writer, numbers, packed
    // lines): a script compiles once per process, and its loop ran mostly as unoptimised first-tier code before the
    // runtime got round to optimising it (docs/performance.md, "The script path in a fresh process").
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void Replay(Action<RobotAction, RobotCursor> emit)
    {
        RobotCursor cursor = NewCursor();
        bool reportIssues = !_kinematicsReported;
        _kinematicsReported = true;
        if (reportIssues)
        {
            // What the cursor notices while applying (a tool defined again, an extruded length it cannot compute) is a warning too.
            cursor.Warn = Warn;
        }
        if (Actions is RobotProgramSnapshot snapshot)
        {
            // A robot's program: indexed chunk by chunk, without an enumerator's two interface calls per action.
            for (int c = 0; c < snapshot.ChunkCount; c++)
            {
                foreach (RobotAction action in snapshot.Chunk(c))
                {
                    ReplayOne(action, cursor, reportIssues, emit);
                }
            }
            return;
        }
        if (Actions is RobotAction[] array)
        {
            // A snapshot array: indexed, without an enumerator's two interface calls per action.
            for (int i = 0; i < array.Length; i++)
            {
                ReplayOne(array[i], cursor, reportIssues, emit);
            }
            return;
        }
        foreach (RobotAction action in Actions)
        {
            ReplayOne(action, cursor, reportIssues, emit);
        }
    }

    /// <summary>One step of <see cref="Replay"/>: applies <paramref name="action"/>, reports what it must, and emits it unless refused.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void ReplayOne(RobotAction action, RobotCursor cursor, bool reportIssues, Action<RobotAction, RobotCursor> emit)
    {
        string? refusal = cursor.TryApply(action);
        if (refusal is not null)
        {
            RefuseFromSource(action, refusal);
            Warn(action, "skipped: " + refusal);
            return;
        }
        if (reportIssues && cursor.LastIssues.Count > 0)
        {
            foreach (KinematicIssue issue in cursor.LastIssues)
            {
                Warn(action, issue);
            }
        }
        emit(action, cursor);
    }

    /// <summary>
    /// The actions with the cursor state after each, for extra passes (e.g. declaring targets) that must not report
    /// refusals a second time: refused actions are skipped silently. The cursor is the same object at every step.
    /// </summary>
    internal IEnumerable<(RobotAction Action, RobotCursor Cursor)> Applied()
    {
        RobotCursor cursor = NewCursor();
        foreach (RobotAction action in Actions)
        {
            string? refusal = cursor.TryApply(action);
            if (refusal is null)
            {
                yield return (action, cursor);
            }
            else
            {
                RefuseFromSource(action, refusal);
            }
        }
    }

    /// <summary>Longest program name: it is also the file name, which file systems limit (255 bytes on most).</summary>
    internal const int MaxProgramNameLength = 100;

    // Names Windows reserves for devices, whatever the extension: a file "CON.mod" cannot be created there.
    private static readonly HashSet<string> WindowsDeviceNames = new(StringComparer.OrdinalIgnoreCase)
    {
        "CON", "PRN", "AUX", "NUL", "COM0", "COM1", "COM2", "COM3", "COM4", "COM5", "COM6", "COM7", "COM8", "COM9",
        "LPT0", "LPT1", "LPT2", "LPT3", "LPT4", "LPT5", "LPT6", "LPT7", "LPT8", "LPT9",
    };

    /// <summary>
    /// A robot name made safe as a program identifier and file name: letters, digits and '_', starting with a letter or '_',
    /// at most <see cref="MaxProgramNameLength"/> characters, '_' appended to a Windows device name (CON, NUL, COM1, …).
    /// </summary>
    internal static string SafeProgramName(string? name)
    {
        if (string.IsNullOrWhiteSpace(name))
        {
            return "Machina";
        }
        var chars = name.Trim().Select(c => char.IsAsciiLetterOrDigit(c) || c == '_' ? c : '_').ToArray();
        string safe = new(chars);
        safe = char.IsAsciiDigit(safe[0]) ? "_" + safe : safe;
        if (safe.Length > MaxProgramNameLength)
        {
            safe = safe[..MaxProgramNameLength];
        }
        return WindowsDeviceNames.Contains(safe) ? safe + "_" : safe;
    }
}

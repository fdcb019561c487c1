using System.Runtime.CompilerServices;
namespace Machina;

/// <summary>
/// A robot you program with simple verbs: <c>MoveTo</c>, <c>Rotate</c>, <c>SpeedTo</c>, <c>Wait</c>… Each verb creates an
/// action that is checked against the robot's current state and then kept for <c>Compile()</c> (offline) or streamed
/// to the controller (online). Verbs ending in <c>To</c> are absolute; the others are relative to the current state.
/// Distances are in millimetres, angles in degrees, speeds in mm/s, times in milliseconds.
/// </summary>
public sealed partial class Robot : IOnlineHost
{
    /// <summary>Guards the issue cursor and the program list; taken before any lock of the online session (see <see cref="IOnlineHost"/>).</summary>
    // A Lock where there is one (.NET 9 on): entered and left in managed code that inlines, where a monitor went through the
    // runtime's native helpers on every issued action (docs/performance.md, session 27).
#if NET9_0_OR_GREATER
    private readonly Lock _issueLock = new();
#else
    private readonly object _issueLock = new();
#endif
    private readonly RobotCursor _issueCursor;

    private readonly RobotProgramActions _programActions = new();
    private int _nextId = 1;

    private Robot(string name, RobotType brand)
    {
        Name = name;
        Brand = brand;
        Logger = new RobotLogger(name);
        // Called while the issue cursor changes, under the issue lock: written once it is released (Robot.IssueLog.cs).
        Action<RobotAction, string> warn = (action, message) => LogLocked(LogLevel.WARNING, $"{action.ToInstruction()} {message}");
        _issueCursor = new RobotCursor { Warn = warn, Notice = warn };
    }

    /// <summary>The library's version.</summary>
    public static string Version => LibraryInfo.Version;

    /// <summary>The robot's name; it is also the name of compiled programs.</summary>
    public string Name { get; }

    /// <summary>The kind of device this robot is, which selects the language it compiles to.</summary>
    public RobotType Brand { get; }

    /// <summary>This robot's log.</summary>
    public RobotLogger Logger { get; }

    /// <summary>Raised after each action is accepted, with the state it leads to. Offline it is raised on the thread that issued the action; online, on the robot's event thread (see <see cref="ActionReleased"/>).</summary>
    public event ActionIssuedHandler? ActionIssued;

    /// <summary>A robot named "Machina" that compiles to a human-readable listing.</summary>
    public static Robot Create() => new("Machina", BrandRegistry.Default.Type);

    /// <summary>A robot with a name (starting with a letter) and a brand.</summary>
    public static Robot Create(string name, RobotType brand)
    {
        ValidateName(name);
        return new Robot(name, EnumText.RequireDefined(brand, nameof(brand)));
    }

    /// <summary>A robot with a name (starting with a letter) and a brand given as text: "ABB", "UR", "KUKA", "ZMORPH", "MARLIN", "HUMAN" or "MACHINA" (any letter case).</summary>
    public static Robot Create(string name, string brand)
    {
        ValidateName(name);
        return new Robot(name, EnumText.Parse<RobotType>(brand, "robot brand", nameof(brand)));
    }

    private static void ValidateName(string? name)
    {
        if (string.IsNullOrWhiteSpace(name) || !char.IsLetter(name[0]))
        {
            throw new ArgumentException($"\"{name}\" is not a valid robot name: it must start with a letter.", nameof(name));
        }
    }

    /// <summary>True when this robot is of the brand named (any letter case).</summary>
    public bool IsBrand(string brand) => string.Equals(Brand.ToString(), brand, StringComparison.OrdinalIgnoreCase);

    /// <summary>True when this robot is of the given brand.</summary>
    public bool IsBrand(RobotType brand) => Brand == brand;

    /// <summary>Text such as <c>Robot["HelloRobot", ABB]</c>.</summary>
    public override string ToString() => $"Robot[\"{Name}\", {Brand}]";

    /// <summary>
    /// Issues an action built by hand. It is checked against the current state; if it cannot be applied an exception explains
    /// why and nothing changes. An action that was already issued is issued again as a copy.
    /// </summary>
    /// <returns>True (kept for programs written for the original Machina).</returns>
    /// <exception cref="ActionRefusedException">The action does not make sense in the current state.</exception>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    public bool Issue(RobotAction action)
    {
        ArgumentNullException.ThrowIfNull(action);
        (string? Report, ActionIssuedArgs? Issued) result;
        List<(LogLevel Level, string Message, RobotAction? Refused)>? lines = null;
        try
        {
            // UnderIssueLock written out for the one action: a script's loop issues millions, and the lambda it took ran as
            // unoptimised first-tier code (a delegate call per action) until the runtime got round to it, after the loop.
            try
            {
                lock (_issueLock)
                {
                    try
                    {
                        result = IssueLocked(action);
                    }
                    finally
                    {
                        lines = TakeLockedLog();
                    }
                }
            }
            finally
            {
                if (lines is not null)
                {
                    WriteLockedLog(lines);
                }
            }
        }
        finally
        {
            _session?.ReleaseIssued();
        }
        RaiseIssued(result.Report, result.Issued);
        return true;
    }

    /// <summary>
    /// Issues actions in order under one lock, so that no other thread's action comes between them; with more than one, every
    /// action is first checked on a copy of the state, so that either all are issued or none. Events are raised after the lock.
    /// </summary>
    private void IssueAll(IReadOnlyList<RobotAction> actions)
    {
        var raised = new List<(string? Report, ActionIssuedArgs? Issued)>(actions.Count);
        try
        {
            UnderIssueLock(actions, (self, list) =>
            {
                if (list.Count > 1)
                {
                    self.DryRun(list);
                }
                foreach (RobotAction action in list)
                {
                    raised.Add(self.IssueLocked(action));
                }
                return true;
            });
        }
        finally
        {
            // Online, the issued actions go to the controller once the lock is released (see IActionStream.ReleaseIssued).
            _session?.ReleaseIssued();
            // Even if an action failed after the dry run, the ones already issued are reported.
            RaiseIssued(raised);
        }
    }

    /// <summary>Logs the state reports and raises ActionIssued for issued actions, outside the lock.</summary>
    private void RaiseIssued(List<(string? Report, ActionIssuedArgs? Issued)> raised)
    {
        foreach ((string? report, ActionIssuedArgs? issued) in raised)
        {
            RaiseIssued(report, issued);
        }
    }

    /// <summary>Logs the state report and raises ActionIssued for one issued action, outside the lock.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void RaiseIssued(string? report, ActionIssuedArgs? issued)
    {
        if (report is not null)
        {
            Logger.Verbose(report);
        }
        if (issued is not null && ActionIssued is { } handler)
        {
            RaiseSafely(handler, issued);
        }
    }

    /// <summary>Applies and records one action; the caller holds the lock. Returns the log report and the event to raise.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private (string? Report, ActionIssuedArgs? Issued) IssueLocked(RobotAction action)
    {
        if (_disposed)
        {
            // The action's text is made only for the message: an issue that goes through never writes it.
            ThrowIfDisposed($"issue {action.ToInstruction().TrimEnd(';')}");
        }
        // The id is claimed atomically before applying, so that an object issued by two robots at once is never shared.
        if (!action.TryClaimId(_nextId))
        {
            action = action.CloneUnissued();
            action.Id = _nextId;
        }
        string? refusal = _session?.WhyCannotStream(action);
        if (refusal is not null)
        {
            action.Id = -1;
            LogLocked(LogLevel.WARNING, $"Refused {action.ToInstruction()}: {refusal}", refused: action);
            throw new ActionRefusedException(action, refusal);
        }
        ActionFrame? frame = null;
        try
        {
            refusal = _session is { } session ? ApplyStreamed(action, session, out frame) : _issueCursor.TryApply(action);
        }
        catch
        {
            action.Id = -1;
            throw;
        }
        if (refusal is not null)
        {
            action.Id = -1;
            LogLocked(LogLevel.WARNING, $"Refused {action.ToInstruction()} {refusal}", refused: action);
            throw new ActionRefusedException(action, refusal);
        }
        _nextId++;
        if (_issueCursor.LastIssues.Count > 0)
        {
            RecordIssues(action, _issueCursor.LastIssues);
        }
        // Report and snapshot are taken under the lock so that they describe exactly this action's result,
        // even when another thread issues the next action before the handlers run.
        string? report = Logger.IsEnabled(LogLevel.VERBOSE) && action.IsRelative ? StateReport() : null;
        ActionIssuedArgs? issued = ActionIssued is not null ? new ActionIssuedArgs(action, _issueCursor.Snapshot()) : null;
        if (_session is not null)
        {
            // Online, the stream raises ActionIssued on its event loop, before any later event about this action.
            _session.Enqueue(action, issued, frame);
            issued = null;
        }
        else
        {
            _programActions.Add(action);
        }
        return (report, issued);
    }

    /// <summary>
    /// Online: applies <paramref name="action"/> to the issue cursor and encodes it from the state it leads to (what is sent is read
    /// from there). When the wire cannot carry it, the action is undone from what it changed (a value copy of the cursor's fields,
    /// and of its collections only the entry the action writes): the cursor is exactly as before. Returns the refusal, or null.
    /// </summary>
    private string? ApplyStreamed(RobotAction action, OnlineSession session, out ActionFrame? frame)
    {
        frame = null;
        RobotCursor.UndoPoint undo = _issueCursor.Mark(action);
        if (_issueCursor.TryApply(action) is string refusal)
        {
            return refusal;
        }
        string? unsendable;
        try
        {
            unsendable = session.Encode(action, _issueCursor, out frame);
        }
        catch
        {
            _issueCursor.Undo(undo);
            throw;
        }
        if (unsendable is not null)
        {
            _issueCursor.Undo(undo);
        }
        return unsendable;
    }

    private string StateReport() => _issueCursor.LastAction switch
    {
        ActionTranslation or ActionArcMotion => $"TCP position at {_issueCursor.Position}",
        ActionRotation => $"TCP orientation at {_issueCursor.Rotation?.ToOrientationString()}",
        ActionTransformation => $"TCP transform at {_issueCursor.Position} {_issueCursor.Rotation?.ToOrientationString()}",
        ActionAxes => $"Axes at {_issueCursor.Axes}",
        _ => $"Settings: {_issueCursor.CurrentSettings}",
    };

    /// <summary>Raises an event; an exception thrown by a subscriber is logged and never stops the robot.</summary>
    internal void RaiseSafely(Delegate handler, MachinaEventArgs args)
    {
        foreach (Delegate subscriber in handler.GetInvocationList())
        {
            try
            {
                switch (subscriber)
                {
                    case ActionIssuedHandler d: d(this, (ActionIssuedArgs)args); break;
                    case ActionReleasedHandler d: d(this, (ActionReleasedArgs)args); break;
                    case ActionExecutedHandler d: d(this, (ActionExecutedArgs)args); break;
                    case MotionUpdateHandler d: d(this, (MotionUpdateArgs)args); break;
                    case EventHandler<ConnectionLostArgs> d: d(this, (ConnectionLostArgs)args); break;
                    case EventHandler<ControllerStoppedArgs> d: d(this, (ControllerStoppedArgs)args); break;
                    case EventHandler<ActionFailedArgs> d: d(this, (ActionFailedArgs)args); break;
                    default: throw new InvalidOperationException($"No way to raise {subscriber.GetType().Name}.");
                }
            }
            catch (Exception ex)
            {
                Logger.Error($"An event handler threw {ex.GetType().Name}: {ex.Message}");
            }
        }
    }
}

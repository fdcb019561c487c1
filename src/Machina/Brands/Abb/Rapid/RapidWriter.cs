using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes the RAPID lines of each action from the cursor state after it: motions with inline or declared targets, settings
/// that RAPID needs as instructions (WorldAccLim), messages, waits, IO, comments, and comment lines plus warnings for
/// what an ABB robot cannot do.
/// </summary>
internal sealed class RapidWriter(CompileJob job, RapidPlan plan, LineSink sink)
{
    /// <summary>Where this writer's lines go.</summary>
    internal LineSink Sink => sink;

    private const string Indent = "    ";
    private const double MinWorldAcc = 0.1;

    private readonly StringBuilder _sb = new(256);
    private readonly bool _inline = job.Options.InlineTargets;
    private readonly bool _human = job.Options.HumanComments;
    private readonly LineNotes _notes = new(job, RapidText.Notes, Indent, () => sink);
    private readonly RapidMoveLine _moveLine = new();
    private int _target;

    /// <summary>Second pass (declared targets only): one <c>CONST robtarget|jointtarget targetN</c> per target; returns how many.</summary>
    internal int DeclareTargets()
    {
        int count = 0;
        foreach ((RobotAction action, RobotCursor cursor) in job.Applied())
        {
            switch (action)
            {
                case ActionTranslation or ActionRotation or ActionTransformation:
                    DeclareRobTarget(count++, cursor.Position!.Value, cursor.Rotation!.Value, cursor, true);
                    break;
                case ActionArcMotion:
                    DeclareRobTarget(count++, cursor.ArcThrough!.Value, cursor.ArcThroughRotation!.Value, cursor, false);
                    DeclareRobTarget(count++, cursor.Position!.Value, cursor.Rotation!.Value, cursor, true);
                    break;
                case ActionAxes:
                    _sb.Clear().Append("  CONST jointtarget target").Append(count++).Append(" := ")
                       .JointTarget(cursor.Axes!.Value, cursor.ExternalAxesJoints).Append(';');
                    sink.Add(_sb.ToString());
                    break;
            }
        }
        return count;
    }

    private void DeclareRobTarget(int n, Vector position, Rotation rotation, RobotCursor cursor, bool end)
    {
        _sb.Clear().Append("  CONST robtarget target").Append(n).Append(" := ")
           .RobTarget(position, rotation, cursor.ExternalAxesCartesian, cursor.ArmAngle, end ? RapidText.Conf(job.Model, cursor) : null).Append(';');
        sink.Add(_sb.ToString());
    }

    /// <summary>
    /// The acceleration limit at the start of main, so that no limit left by an earlier program stays in force:
    /// off for Machina's built-in default (the controller's own acceleration), else the start state's value.
    /// </summary>
    internal string StartAcceleration()
    {
        double acc = job.NewCursor().Acceleration;
        if (acc == Settings.Default.Acceleration || acc < 0.001)
        {
            return Indent + "WorldAccLim \\Off;";
        }
        return Indent + "WorldAccLim \\On := " + NumAppend.Format(Math.Max(acc / 1000, MinWorldAcc), 6) + ";";
    }

    /// <summary>Final pass: the instruction lines of every action, in order (refused actions are reported as warnings).</summary>
    internal void WriteInstructions() => job.Replay(Write);

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void Write(RobotAction action, RobotCursor cursor)
    {
        if (plan.IsLive)
        {
            plan.Observe(action, cursor);
        }
        if (action is ActionTranslation or ActionRotation or ActionTransformation)
        {
            string start = cursor.MotionType == MotionType.Joint ? Indent + "MoveJ " : Indent + "MoveL ";
            if (!_inline || !WriteInlineMove(start, action, cursor))
            {
                _sb.Clear().Append(start);
                RobTargetOrName(cursor.Position!.Value, cursor.Rotation!.Value, cursor, true);
                MoveCode(action, cursor);
            }
            return;
        }
        WriteOther(action, cursor);
    }

    /// <summary>
    /// The lines of every action but a linear or joint move. Apart from <see cref="Write"/>, which the runtime compiles fully
    /// optimised at its first call: that compile of the whole switch, with everything it inlines, was a few milliseconds of every
    /// fresh process's compile, for the rare actions.
    /// </summary>
    private void WriteOther(RobotAction action, RobotCursor cursor)
    {
        switch (action)
        {
            case ActionArcMotion arc:
                if (ArcOrientation.ThroughIsIgnored(arc, cursor))
                {
                    job.Warn(action, "MoveC turns the tool evenly from the start to the end orientation; the orientation asked for at the through point is not used.");
                }
                _sb.Clear().Append(Indent).Append("MoveC ");
                RobTargetOrName(cursor.ArcThrough!.Value, cursor.ArcThroughRotation!.Value, cursor, false);
                _sb.Append(", ");
                RobTargetOrName(cursor.Position!.Value, cursor.Rotation!.Value, cursor, true);
                MoveCode(action, cursor);
                break;
            case ActionAxes:
                _sb.Clear().Append(Indent).Append("MoveAbsJ ");
                if (_inline)
                {
                    _sb.JointTarget(cursor.Axes!.Value, cursor.ExternalAxesJoints);
                }
                else
                {
                    _sb.Append("target").Append(_target++);
                }
                MoveCode(action, cursor);
                break;
            case ActionAcceleration:
                Code(action, AccelerationLine(action, cursor.Acceleration));
                break;
            case ActionPushPop { Push: false } when cursor.SettingsBeforeLastPop is Settings before
                                                   && Math.Abs(before.Acceleration - cursor.Acceleration) >= 0.001:
                Code(action, AccelerationLine(action, cursor.Acceleration));
                break;
            case ActionSpeed when Math.Round(cursor.Speed, 3) < RapidPlan.MinSpeed:
                job.Warn(action, $"RAPID speeddata is written with 3 decimals; {Num.G(cursor.Speed)} mm/s would be 0 and was raised to {Num.G(RapidPlan.MinSpeed)} mm/s.");
                _notes.NoCode(action);
                break;
            case ActionMessage m:
                WriteMessage(m);
                break;
            case ActionWait w:
                Code(action, Indent + "WaitTime " + ProgramText.Seconds(w.Millis) + ";");
                break;
            case ActionComment c:
                sink.Add(Indent + "! " + RapidText.CommentText(c.Comment));
                break;
            case ActionDefineTool d:
                Code(action, Indent + "! Tool \"" + d.Tool.Name + "\" defined");
                break;
            case ActionAttachTool:
                WriteAttach(action, cursor.Tool!);
                break;
            case ActionDetachTool:
                Code(action, Indent + "! All tools detached");
                break;
            case ActionIODigital io:
                WriteSignal(action, io.PinName, "SetDO ", io.On ? "1" : "0");
                break;
            case ActionIOAnalog io:
                WriteSignal(action, io.PinName, "SetAO ", new StringBuilder(16).AppendFixed(io.Value, 6).ToString());
                break;
            case ActionReadInput read:
                // DInput and AInput return the signal's value; the module declares machina_di (dionum) and machina_ai (num).
                WriteSignal(action, read.PinName, read.IsAnalog ? "machina_ai := AInput(" : "machina_di := DInput(", null);
                break;
            case ActionWaitDigital wait:
                // WaitDI without \TimeFlag: when \MaxTime passes, the error ERR_WAIT_MAXTIME stops the program.
                WriteSignal(action, wait.PinName, "WaitDI ", (wait.On ? "1" : "0") + (wait.TimeoutMillis > 0 ? "\\MaxTime:=" + ProgramText.Seconds(wait.TimeoutMillis) : ""));
                break;
            case ActionCustomCode { IsDeclaration: false } code:
                Code(action, Indent + code.Statement);
                break;
            case ActionTemperature:
                Unsupported(action, "an ABB robot has no heaters to control; the temperature was not set.");
                break;
            case ActionExtrusion or ActionExtrusionRate:
                Unsupported(action, "an ABB robot has no extruder; use CustomCode or IO to drive one.");
                break;
            case ActionInitialization:
                sink.Add(Indent + "! " + action.Describe() + " (nothing to do on an ABB robot)");
                break;
            case ActionExternalAxis or ActionArmAngle:
                WarnArmAngleConflict(action, cursor);
                _notes.NoCode(action);
                break;
            case ActionSpeed or ActionPrecision or ActionMotionMode or ActionCoordinates or ActionPushPop or ActionCustomCode:
                // Settings travel in the next motion's speeddata and zonedata; declarations are written at the top.
                _notes.NoCode(action);
                break;
            default:
                throw ActionKinds.Unhandled(action, "The RAPID writer");
        }
    }

    /// <summary>The target inline or by name; <paramref name="end"/>: the motion's end point, whose confdata is known with a model.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void RobTargetOrName(Vector position, Rotation rotation, RobotCursor cursor, bool end)
    {
        if (_inline)
        {
            _moveLine.Targets.Append(_sb, position, rotation, cursor.ExternalAxesCartesian, cursor.ArmAngle, end ? RapidText.Conf(job.Model, cursor) : null);
        }
        else
        {
            _sb.Append("target").Append(_target++);
        }
    }

    /// <summary>A linear or joint move with an inline target written as one line by <see cref="RapidMoveLine"/>; false when it could not.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private bool WriteInlineMove(string start, RobotAction action, RobotCursor cursor)
    {
        return _moveLine.TryWrite(sink, start, cursor.Position!.Value, cursor.Rotation!.Value, cursor.ExternalAxesCartesian, cursor.ArmAngle,
                                  RapidText.Conf(job.Model, cursor), plan.SpeedName(cursor.Speed), plan.ZoneName(cursor.Precision),
                                  plan.ToolName(cursor.Tool), action, _human);
    }

    /// <summary>Ends the move instruction begun in the builder (speed, zone, tool, work object), adds its comment and writes the line.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void MoveCode(RobotAction action, RobotCursor cursor)
    {
        _sb.Append(", ").Append(plan.SpeedName(cursor.Speed)).Append(", ").Append(plan.ZoneName(cursor.Precision))
           .Append(", ").Append(plan.ToolName(cursor.Tool)).Append("\\WObj:=WObj0;");
        EndLine(action);
    }

    /// <summary>Adds the action's comment (with human comments) to the line in the builder and writes it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private void EndLine(RobotAction action)
    {
        if (_human)
        {
            _sb.Append("  ! [").AppendDescription(action).Append(']');
        }
        sink.Add(_sb);
    }

    private string AccelerationLine(RobotAction action, double acceleration)
    {
        if (acceleration < 0.001)
        {
            return Indent + "WorldAccLim \\Off;";
        }
        double perSecond = acceleration / 1000;
        if (Math.Round(perSecond, 6) < MinWorldAcc)
        {
            job.Warn(action, $"ABB controllers accept world acceleration limits from {Num.G(MinWorldAcc)} m/s^2 (100 mm/s^2); " +
                             $"{Num.G(acceleration)} mm/s^2 was raised to that minimum.");
            perSecond = MinWorldAcc;
        }
        return Indent + "WorldAccLim \\On := " + NumAppend.Format(perSecond, 6) + ";";
    }

    private void WriteMessage(ActionMessage m)
    {
        List<string> literals = RapidText.StringLiterals(m.Message, out bool split, out bool changed);
        if (split)
        {
            job.Warn(m, $"RAPID strings hold at most {RapidText.MaxStringLength} characters; the message was split over several TPWrite lines.");
        }
        if (changed)
        {
            job.Warn(m, "characters that are not printable ASCII were replaced by '?' in the message.");
        }
        // The human comment goes on the first line only: repeated on each piece of a long message it grew with its square.
        Code(m, Indent + "TPWrite " + literals[0] + ";");
        for (int i = 1; i < literals.Count; i++)
        {
            sink.Add(Indent + "TPWrite " + literals[i] + ";");
        }
    }

    private void WriteAttach(RobotAction action, Tool tool)
    {
        string? declared = plan.DeclaredToolName(tool);
        string name = declared ?? tool.Name;
        if (declared is not null && declared != tool.Name)
        {
            job.Warn(action, $"tool \"{tool.Name}\" is declared as \"{declared}\" in RAPID (its name is taken, reserved or too long).");
        }
        if (declared is not null && tool.Weight < RapidText.MinToolMass)
        {
            job.Warn(action, $"RAPID needs a tool mass above 0; tool \"{tool.Name}\" is declared with {Num.G(RapidText.MinToolMass)} kg.");
        }
        Code(action, Indent + "! Tool \"" + name + "\" attached");
    }

    /// <summary>An IO instruction on a named signal (<paramref name="value"/> after it), or a function call on it when <paramref name="value"/> is null.</summary>
    private void WriteSignal(RobotAction action, string pin, string instruction, string? value)
    {
        if (RapidNames.WhyNotSignal(pin) is string why)
        {
            Unsupported(action, why);
            return;
        }
        Code(action, Indent + instruction + pin + (value is null ? ");" : ", " + value + ";"));
    }

    private void WarnArmAngleConflict(RobotAction action, RobotCursor cursor)
    {
        if (cursor.ArmAngle is not null && cursor.ExternalAxesCartesian?[1] is not null)
        {
            job.Warn(action, "the arm angle and cartesian external axis 1 share the same robtarget field (eax_a); the arm angle is written.");
        }
    }

    private void Unsupported(RobotAction action, string reason)
    {
        job.Warn(action, reason);
        sink.Add(Indent + "! NOT SUPPORTED ON ABB: " + RapidText.CommentText(action.Describe()));
    }

    private void Code(RobotAction action, string line)
    {
        _sb.Clear().Append(line);
        EndLine(action);
    }
}

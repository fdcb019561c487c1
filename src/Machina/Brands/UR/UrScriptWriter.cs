using System.Text;

namespace Machina;

/// <summary>
/// Writes the URScript lines of each action from the cursor state after it: motions with inline or variable targets,
/// tool changes (TCP and payload), messages, waits, IO, comments, and comment lines plus warnings for what a UR robot cannot do.
/// </summary>
internal sealed class UrScriptWriter(CompileJob job, WarningRuns sink)
{
    private const string Indent = "  ";

    private readonly StringBuilder _sb = new(256);
    private readonly char[] _instruction = new char[Math.Max(RobotAction.MaxWrittenInstructionChars, ActionTranslation.MaxInstructionChars)];
    private readonly bool _inline = job.Options.InlineTargets;
    private readonly bool _human = job.Options.HumanComments;
    private readonly LineNotes _notes = new(job, UrScriptText.Notes, Indent, () => sink);
    private readonly UrRepeatedText _repeated = new();
    private readonly TranslationDigits _digits = new();
    private readonly KeptNumber _radiusText = new(), _lengthText = new(), _halfText = new();
    private UrMoveLine? _moveLine;
    private int _target;
    private RobotAction? _lastMotion;
    private double _lastRadius;
    private bool _lastRadiusWarned;

    /// <summary>Second pass (variable targets only): one <c>targetN=…</c> per target, numbered 0, 1, 2… ; returns how many.</summary>
    internal int DeclareTargets()
    {
        int count = 0;
        foreach ((RobotAction action, RobotCursor cursor) in job.Applied())
        {
            switch (action)
            {
                case ActionTranslation or ActionRotation or ActionTransformation:
                    _repeated.Pose(Declare(count++), cursor.Position!.Value, cursor.Rotation!.Value);
                    break;
                case ActionArcMotion:
                    _repeated.Pose(Declare(count++), cursor.ArcThrough!.Value, cursor.ArcThroughRotation!.Value);
                    sink.Add(_sb.ToString());
                    _repeated.Pose(Declare(count++), cursor.Position!.Value, cursor.Rotation!.Value);
                    break;
                case ActionAxes:
                    Declare(count++).JointList(cursor.Axes!.Value);
                    break;
                default:
                    continue;
            }
            sink.Add(_sb.ToString());
        }
        return count;
    }

    private StringBuilder Declare(int n) => _sb.Clear().Append(Indent).Append("target").Append(n).Append('=');

    /// <summary>When the program starts with a tool already attached, sets its TCP and payload first.</summary>
    internal void WriteStartTool()
    {
        if (job.NewCursor().Tool is Tool tool)
        {
            sink.Add(UrScriptText.SetTcp(tool));
            sink.Add(UrScriptText.SetPayload(tool));
        }
    }

    /// <summary>Final pass: the instruction lines of every action, in order (refused actions are reported as warnings).</summary>
    internal void WriteInstructions()
    {
        job.Replay(Write);
        sink.EndRun();
    }

    private void Write(RobotAction action, RobotCursor cursor)
    {
        if (action is ActionTranslation or ActionRotation or ActionTransformation or ActionArcMotion or ActionAxes)
        {
            CheckBlend(action, cursor);
            CheckJointSpeed(action, cursor);
            sink.Motion();
        }
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                bool joint = cursor.MotionType == MotionType.Joint;
                if (_inline && (_moveLine ??= new UrMoveLine(_repeated, _digits)).TryWrite(sink, action, cursor, joint, _human))
                {
                    break;
                }
                _sb.Clear().Append(Indent).Append(joint ? "movej(" : "movep(");
                PoseOrName(cursor.Position!.Value, cursor.Rotation!.Value);
                _repeated.MotionParameters(_sb, cursor.Acceleration, cursor.Speed, cursor.Precision, joint);
                EndLine(action);
                break;
            case ActionArcMotion arc:
                if (ArcOrientation.ThroughIsIgnored(arc, cursor))
                {
                    job.Warn(action, "movec turns the tool evenly from the start to the end orientation; the orientation asked for at the through point is not used.");
                }
                _sb.Clear().Append(Indent).Append("movec(");
                PoseOrName(cursor.ArcThrough!.Value, cursor.ArcThroughRotation!.Value);
                _sb.Append(", ");
                PoseOrName(cursor.Position!.Value, cursor.Rotation!.Value);
                _repeated.MotionParameters(_sb, cursor.Acceleration, cursor.Speed, cursor.Precision, joint: false);
                EndLine(action);
                break;
            case ActionAxes:
                _sb.Clear().Append(Indent).Append("movej(");
                if (_inline)
                {
                    _sb.JointList(cursor.Axes!.Value);
                }
                else
                {
                    _sb.Append("target").Append(_target++);
                }
                _repeated.MotionParameters(_sb, cursor.Acceleration, cursor.Speed, cursor.Precision, joint: true);
                EndLine(action);
                break;
            case ActionSpeed when UrScriptText.RoundsToZero(cursor.Speed):
                job.Warn(action, $"URScript speeds are written in m/s with 6 decimals; {Num.G(cursor.Speed)} mm/s would be 0 and was raised to {NumAppend.Format(UrScriptText.MinRate, 6)} m/s.");
                _notes.NoCode(action);
                break;
            case ActionAcceleration when UrScriptText.RoundsToZero(cursor.Acceleration):
                job.Warn(action, $"URScript accelerations are written in m/s^2 with 6 decimals; {Num.G(cursor.Acceleration)} mm/s^2 would be 0 and was raised to {NumAppend.Format(UrScriptText.MinRate, 6)} m/s^2.");
                _notes.NoCode(action);
                break;
            case ActionMessage m:
                string literal = UrScriptText.StringLiteral(m.Message, out bool changed);
                if (changed)
                {
                    job.Warn(m, "URScript strings cannot hold quotes, backslashes, line breaks or non-ASCII characters; they were replaced (\" by ', \\ by /, line breaks by spaces, others by ?).");
                }
                Code(action, Indent + "popup(" + literal + ", title=\"Machina Message\", warning=False, error=False)");
                break;
            case ActionWait w:
                Code(action, Indent + "sleep(" + ProgramText.Seconds(w.Millis) + ")");
                break;
            case ActionComment c:
                sink.Add(Indent + "# " + UrScriptText.CommentText(c.Comment));
                break;
            case ActionDefineTool d:
                Code(action, Indent + "# Tool \"" + d.Tool.Name + "\" defined");
                break;
            case ActionAttachTool or ActionDetachTool:
                Code(action, UrScriptText.SetTcp(cursor.Tool));
                Code(action, UrScriptText.SetPayload(cursor.Tool));
                break;
            case ActionIODigital io:
                WriteDigital(io);
                break;
            case ActionIOAnalog io:
                WriteAnalog(io);
                break;
            case ActionWaitDigital wait:
                WriteWaitDigital(wait);
                break;
            case ActionReadInput read:
                if (UrInputs.WhyNot(read) is string problem)
                {
                    Unsupported(read, problem);
                    break;
                }
                Code(read, Indent + (read.IsAnalog ? "machina_ai = " : "machina_di = ") + UrInputs.ReadCall(read));
                break;
            case ActionCustomCode { IsDeclaration: false } code:
                Code(action, Indent + code.Statement);
                break;
            case ActionTemperature:
                Unsupported(action, "a UR robot has no heaters to control; the temperature was not set.");
                break;
            case ActionExtrusion or ActionExtrusionRate:
                Unsupported(action, "a UR robot has no extruder; use CustomCode or IO to drive one.");
                break;
            case ActionExternalAxis:
                Unsupported(action, "URScript programs here drive the six arm joints only; external axes are not written.");
                break;
            case ActionArmAngle:
                Unsupported(action, "UR arms have six joints and no arm angle (it exists only on 7-axis robots).");
                break;
            case ActionInitialization:
                sink.Add(Indent + "# " + action.Describe() + " (nothing to do on a UR robot)");
                break;
            case ActionSpeed or ActionAcceleration or ActionPrecision or ActionMotionMode or ActionCoordinates or ActionPushPop or ActionCustomCode:
                // Settings travel as the next motion's a, v and r arguments; declarations are written at the top.
                _notes.NoCode(action);
                break;
            default:
                throw ActionKinds.Unhandled(action, "The URScript writer");
        }
    }

    /// <summary>
    /// Blends on a UR cannot overlap: UR's manual (PolyScope, "Blend parameters") says a warning is logged when two do, and the
    /// program runs on; the twin then blends with half of the shorter segment. A blend radius should be at most half of each
    /// segment it joins. Checks this motion's segment against its own radius and the previous motion's.
    /// </summary>
    private void CheckBlend(RobotAction action, RobotCursor cursor)
    {
        if (cursor.LastPathLength is double length)
        {
            if (_lastMotion is not null && !_lastRadiusWarned && _lastRadius > length / 2)
            {
                WarnBlend(_lastMotion, _lastRadius, length, "the next"u8);
            }
            if (cursor.Precision > length / 2)
            {
                WarnBlend(action, cursor.Precision, length, "this"u8);
                _lastRadiusWarned = true;
            }
            else
            {
                _lastRadiusWarned = false;
            }
        }
        else
        {
            _lastRadiusWarned = false;
        }
        _lastMotion = action;
        _lastRadius = cursor.Precision;
    }

    /// <summary>Records the warning and writes it into the script too, as a comment just before the motion that reveals it.</summary>
    /// <remarks>
    /// A long program of short moves warns on every motion, so the comment line is written as ASCII bytes straight into the
    /// file's buffer (<see cref="WarningRuns.BeginWarnAscii"/>): numbers formatted in place (G15, as <see cref="Num.G"/>, through
    /// <see cref="NumShortest"/>; the radius and the length kept from the last warning, <see cref="KeptNumber"/>), a move's
    /// instruction through its digits shared with the line's description (<see cref="TranslationDigits"/>); only the text of other
    /// actions is made comment-safe, since the rest is fixed text and numbers. The warning's own string is made only while the
    /// job keeps warnings.
    /// </remarks>
    private void WarnBlend(RobotAction action, double radius, double length, ReadOnlySpan<byte> which)
    {
        if (!job.KeepsMoreWarnings && sink.Continues("blend"))
        {
            // The run of blend warnings goes on and the job only counts warnings by now: the text would be written nowhere.
            job.Warn(action, "");
            sink.Warn("blend", []);
            return;
        }
        // A move's instruction is digits and fixed words, safe in a comment as it is: no string. When its numbers are the digits
        // it shares with its description it is written as bytes in its place in the line.
        Span<byte> line = default;
        int at = 0, shared = -1;
        if (action is ActionTranslation translation)
        {
            line = sink.BeginWarnAscii(BlendWarningChars + ActionTranslation.MaxInstructionChars);
            at = Put(line, 0, "  # WARNING: "u8);
            shared = _digits.TryWriteInstructionAscii(translation, line[at..]);
        }
        if (shared >= 0)
        {
            at += shared;
        }
        else
        {
            int ownLength = action is ActionTranslation move ? move.WriteInstruction(_instruction) : action.TryWriteInstruction(_instruction);
            string? instruction = ownLength < 0 ? UrScriptText.CommentText(action.ToInstruction()) : null;
            ReadOnlySpan<char> quoted = instruction is null ? _instruction.AsSpan(0, ownLength) : instruction;
            line = sink.BeginWarnAscii(BlendWarningChars + quoted.Length);
            at = Put(line, 0, "  # WARNING: "u8);
            at += Narrow(quoted, line[at..]);
        }
        line[at++] = (byte)' ';
        int start = at;
        at = Put(line, at, "the blend radius of "u8);
        at = _radiusText.WriteAscii(line, at, radius);
        at = Put(line, at, " mm is more than half of "u8);
        at = Put(line, at, which);
        at = Put(line, at, " motion ("u8);
        at = _lengthText.WriteAscii(line, at, Math.Round(length, 3));
        at = Put(line, at, " mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo("u8);
        at = _halfText.WriteAscii(line, at, Math.Floor(length / 2 * 1000) / 1000);
        at = Put(line, at, ") or less around short motions."u8);
        if (job.KeepsMoreWarnings)
        {
            job.Warn(action, Encoding.ASCII.GetString(line[start..at]));
        }
        else
        {
            job.Warn(action, "");
        }
        // Consecutive motions with this warning get one comment after them (WarningRuns), not one each.
        sink.EndWarnAscii("blend", at);
    }

    /// <summary>Characters enough for a blend warning's line besides the instruction it quotes: fixed text and three numbers.</summary>
    private const int BlendWarningChars = 288 + 3 * NumAppend.MaxChars;

    /// <summary>The ASCII bytes of <paramref name="text"/> (a character outside ASCII as <c>?</c>, as the file would hold it); returns their count.</summary>
    private static int Narrow(ReadOnlySpan<char> text, Span<byte> destination) =>
        AsciiNarrow.TryWrite(text, destination) is int written and >= 0 ? written : Encoding.ASCII.GetBytes(text, destination);

    /// <summary>Copies <paramref name="text"/> into <paramref name="line"/> at <paramref name="at"/>; returns the position after it.</summary>
    private static int Put(Span<byte> line, int at, ReadOnlySpan<byte> text)
    {
        text.CopyTo(line[at..]);
        return at + text.Length;
    }

    /// <summary>
    /// movej takes the speed as the speed of the joint that moves most, in °/s (written in rad/s): warn when it is above that joint's
    /// maximum for the robot's model (without known joints, above every joint's maximum).
    /// </summary>
    private void CheckJointSpeed(RobotAction action, RobotCursor cursor)
    {
        if (job.Model?.MaxJointSpeeds is not Joints max || !(action is ActionAxes || cursor.MotionType == MotionType.Joint) || action is ActionArcMotion)
        {
            return;
        }
        int joint = 0;
        if (cursor.PrevAxes is Joints before && cursor.Axes is Joints after)
        {
            for (int k = 1; k < Joints.Count; k++)
            {
                if (Math.Abs(after[k] - before[k]) > Math.Abs(after[joint] - before[joint]))
                {
                    joint = k;
                }
            }
        }
        else
        {
            for (int k = 1; k < Joints.Count; k++)
            {
                if (max[k] > max[joint])
                {
                    joint = k;
                }
            }
        }
        if (cursor.Speed > max[joint])
        {
            job.Warn(action, $"joint motions take the speed as the speed of the joint that moves most, in degrees per second: {Num.G(cursor.Speed)}°/s is above the {job.Model.Name}'s maximum of {Num.G(max[joint])}°/s for joint {joint + 1}. Use SpeedTo({Num.G(max[joint])}) or less for joint motions.");
        }
    }

    private void PoseOrName(Vector position, Rotation rotation)
    {
        if (_inline)
        {
            _repeated.Pose(_sb, position, rotation);
        }
        else
        {
            _sb.Append("target").Append(_target++);
        }
    }

    private void WriteDigital(ActionIODigital io)
    {
        if (UrOutputs.WhyNot(io) is string problem)
        {
            Unsupported(io, problem);
            return;
        }
        string function = io.IsToolPin ? "set_tool_digital_out(" : "set_standard_digital_out(";
        Code(io, Indent + function + Num.I(io.PinNumber) + ", " + (io.On ? "True" : "False") + ")");
    }

    /// <summary>
    /// A loop that reads the input once per controller step (sync); with a time limit it counts the steps' time
    /// (get_steptime) and, when the limit passes, shows an error popup and halts the program.
    /// </summary>
    private void WriteWaitDigital(ActionWaitDigital wait)
    {
        if (UrInputs.WhyNot(wait) is string problem)
        {
            Unsupported(wait, problem);
            return;
        }
        string read = UrInputs.ReadCall(wait) + " != " + (wait.On ? "True" : "False");
        if (wait.TimeoutMillis == 0)
        {
            Code(wait, Indent + "while " + read + ":");
            sink.Add(Indent + "  sync()");
            sink.Add(Indent + "end");
            return;
        }
        Code(wait, Indent + "machina_waited = 0");
        sink.Add(Indent + "while " + read + ":");
        sink.Add(Indent + "  if machina_waited >= " + ProgramText.Seconds(wait.TimeoutMillis) + ":");
        sink.Add(Indent + "    popup(\"" + UrInputs.TimeoutText(wait) + "\", \"Machina\", error=True)");
        sink.Add(Indent + "    halt");
        sink.Add(Indent + "  end");
        sink.Add(Indent + "  sync()");
        sink.Add(Indent + "  machina_waited = machina_waited + get_steptime()");
        sink.Add(Indent + "end");
    }

    private void WriteAnalog(ActionIOAnalog io)
    {
        if (UrOutputs.WhyNot(io) is string problem)
        {
            Unsupported(io, problem);
            return;
        }
        Code(io, Indent + "set_standard_analog_out(" + Num.I(io.PinNumber) + ", " + Num.F(io.Value, 3) + ")");
    }

    private void Unsupported(RobotAction action, string reason)
    {
        job.Warn(action, reason);
        sink.Add(Indent + "# NOT SUPPORTED ON UR: " + UrScriptText.CommentText(action.Describe()));
    }

    /// <summary>Adds the action's comment (with human comments) to the line in the builder and writes it.</summary>
    private void EndLine(RobotAction action)
    {
        if (_human)
        {
            _sb.Append("  # [").AppendDescription(action).Append(']');
        }
        sink.Add(_sb);
    }

    private void Code(RobotAction action, string line)
    {
        _sb.Clear().Append(line);
        EndLine(action);
    }
}

using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes one KRL program from the state after each action (never re-deriving it): the <c>.src</c> file, and the <c>.dat</c> file
/// when targets are declared instead of inline. One writer per compile; it keeps only small per-program counters.
/// </summary>
internal sealed class KrlWriter
{
    private const string Indent = "  ";

    /// <summary>Variable that keeps the controller's default CP acceleration, for Machina's "acceleration 0 = controller default".</summary>
    internal const string AccDefaultVariable = "machina_acc_cp";

    private readonly Compiler _compiler;
    private readonly CompileJob _job;
    private readonly LineNotes _notes;
    private readonly ProgramOutput _output;
    private readonly bool _human;
    private readonly bool _inline;
    private readonly StringBuilder _line = new(160);
    private readonly StringBuilder _declaration = new(160);
    private LineSink _src = null!;
    private LineSink? _dat;
    private int _targetCount;
    private bool _ptpSpeedWarned;
    private bool _usesAccDefault;

    internal KrlWriter(Compiler compiler, CompileJob job, ProgramOutput output)
    {
        _compiler = compiler;
        _job = job;
        _notes = new LineNotes(job, ProgramNotes.Semicolon, Indent, () => _src, Code);
        _output = output;
        _human = job.Options.HumanComments;
        _inline = job.Options.InlineTargets;
    }

    /// <summary>Writes the whole program.</summary>
    internal void Write()
    {
        string module = KrlText.ModuleName(_job.ProgramName);
        RobotCursor start = _job.NewCursor();
        _usesAccDefault = _job.SetsAcceleration;
        _src = _output.OpenFile(module, "src", RobotProgram.Ascii, _compiler.CommentPrefix);
        if (!_inline)
        {
            _dat = _output.OpenFile(module, "dat", RobotProgram.Ascii, _compiler.CommentPrefix);
            WriteDatStart(module);
        }
        WriteSrcStart(module, start);
        _job.Replay(EmitAction);
        _src.Add("");
        _src.Add("END");
        if (_dat is not null)
        {
            _dat.Add("");
            _dat.Add("ENDDAT");
        }
    }

    private void WriteHeader(LineSink file, string module)
    {
        file.AddRange(_compiler.Header(_job));
        if (module != _job.ProgramName)
        {
            file.Add($"; KRL module name \"{module}\": the program name \"{_job.ProgramName}\" adapted to KRL's naming rules (24 characters, no keywords).");
        }
    }

    private void WriteDatStart(string module)
    {
        LineSink dat = _dat!;
        dat.Add("&ACCESS RVP");
        dat.Add("&REL 1");
        dat.Add("DEFDAT " + module);
        WriteHeader(dat, module);
        dat.Add("");
    }

    private void WriteSrcStart(string module, RobotCursor start)
    {
        LineSink src = _src;
        src.Add("&ACCESS RVP");
        src.Add("&REL 1");
        src.Add(@"&PARAM TEMPLATE = C:\KRC\Roboter\Template\vorgabe");
        src.Add("&PARAM EDITMASK = *");
        src.Add("DEF " + module + "( )");
        WriteHeader(src, module);
        src.Add("");

        bool declared = false;
        foreach (string statement in _job.CustomDeclarations)
        {
            src.Add(Indent + statement);
            declared = true;
        }
        if (_usesAccDefault)
        {
            src.Add(Indent + "DECL REAL " + AccDefaultVariable);
            declared = true;
        }
        if (_job.ReadsDigital)
        {
            src.Add(Indent + "DECL BOOL machina_di");
            declared = true;
        }
        if (_job.ReadsAnalog)
        {
            src.Add(Indent + "DECL REAL machina_ai");
            declared = true;
        }
        if (declared)
        {
            src.Add("");
        }

        src.Add(";FOLD INI");
        src.Add("  ;FOLD BASISTECH INI");
        src.Add("    GLOBAL INTERRUPT DECL 3 WHEN $STOPMESS==TRUE DO IR_STOPM ( )");
        src.Add("    INTERRUPT ON 3");
        src.Add("    BAS (#INITMOV,0 )");
        src.Add("  ;ENDFOLD (BASISTECH INI)");
        src.Add(";ENDFOLD (INI)");
        src.Add("");
        if (_human)
        {
            src.Add(Indent + "; BCO run on the spot, then Machina's starting frames and settings");
        }
        src.Add(Indent + "PTP $AXIS_ACT");
        if (_usesAccDefault)
        {
            src.Add(Indent + AccDefaultVariable + " = $ACC.CP");
        }
        src.Add(Indent + "$BASE = $NULLFRAME");
        src.Add(Indent + "$TOOL = " + (start.Tool is Tool tool ? KrlFormat.ToolFrame(tool) : "$NULLFRAME"));
        src.Add(Indent + "$ADVANCE = 3");
        src.Add(Indent + VelocityLine(start.Speed));
        if (!Settings.MeansControllerAcceleration(start.Acceleration))
        {
            src.Add(Indent + AccelerationLine(start.Acceleration));
        }
        src.Add(Indent + PrecisionLine(start.Precision));
        src.Add("");
    }

    private static string VelocityLine(double speed) => "$VEL.CP = " + KrlFormat.SpeedMetresPerSecond(speed);

    private static string AccelerationLine(double acceleration) =>
        "$ACC.CP = " + (Settings.MeansControllerAcceleration(acceleration) ? AccDefaultVariable : KrlFormat.AccelerationMetresPerSecond2(acceleration));

    private static string PrecisionLine(double precision) => "$APO.CDIS = " + KrlFormat.Mm(precision);

    private void EmitAction(RobotAction action, RobotCursor c)
    {
        switch (action)
        {
            case ActionSpeed:
                WarnIfRaised(action, c.Speed, "speed", "mm/s", "m/s");
                Code(VelocityLine(c.Speed), action);
                break;
            case ActionAcceleration:
                WarnIfRaised(action, c.Acceleration, "acceleration", "mm/s^2", "m/s^2");
                Code(AccelerationLine(c.Acceleration), action);
                break;
            case ActionPrecision:
                Code(PrecisionLine(c.Precision), action);
                break;
            case ActionPushPop { Push: false }:
                EmitRestoredSettings(action, c);
                break;
            case ActionTranslation or ActionRotation or ActionTransformation:
                EmitCartesian(action, c);
                break;
            case ActionArcMotion:
                EmitArc(action, c);
                break;
            case ActionAxes:
                EmitAxes(action, c);
                break;
            case ActionWait wait:
                Code("WAIT SEC " + KrlFormat.Seconds(wait.Millis), action);
                break;
            case ActionMessage message:
                _job.Warn(action, "KRL has no plain instruction to show a message; it is written as a comment.");
                Code("; MESSAGE: " + KrlText.Comment(message.Message), action);
                break;
            case ActionComment comment:
                _src.Add(Indent + "; " + KrlText.Comment(comment.Comment));
                break;
            case ActionCustomCode { IsDeclaration: false } custom:
                Code(custom.Statement, action);
                break;
            case ActionAttachTool:
                EmitAttach(action, c);
                break;
            case ActionDetachTool:
                Code("$TOOL = $NULLFRAME", action);
                break;
            case ActionIODigital digital:
                EmitOutput(action, digital.PinName, digital.IsToolPin, digital.On ? "TRUE" : "FALSE", "$OUT", 4096);
                break;
            case ActionWaitDigital wait:
                EmitWaitDigital(wait);
                break;
            case ActionReadInput read:
                EmitRead(read);
                break;
            case ActionIOAnalog analog:
                if (analog.Value < -1 || analog.Value > 1)
                {
                    _notes.Error(action, $"KRL analog outputs take values from -1 to 1, and {Num.G(analog.Value)} is outside that range.");
                }
                else
                {
                    EmitOutput(action, analog.PinName, analog.IsToolPin, KrlFormat.Fine(analog.Value), "$ANOUT", 32);
                }
                break;
            case ActionDefineTool or ActionExternalAxis or ActionMotionMode or ActionCoordinates or ActionPushPop or ActionCustomCode:
                // Custom declarations are written in the declaration section.
                _notes.NoCode(action);
                break;
            case ActionArmAngle:
                _notes.NotApplicable(action, "KUKA arms of this kind have no arm angle to set.");
                break;
            case ActionTemperature or ActionExtrusion or ActionExtrusionRate:
                _notes.NotApplicable(action, "a KUKA arm has no extruder or heated parts; this is for 3D printers.");
                break;
            case ActionInitialization:
                _notes.NotApplicable(action, "a KUKA program needs no start-up or shut-down sequence; this is for 3D printers.");
                break;
            default:
                throw ActionKinds.Unhandled(action, "The KRL writer");
        }
    }

    private void WarnIfRaised(RobotAction action, double value, string what, string unit, string krlUnit)
    {
        if (KrlFormat.RoundsToZero(value))
        {
            _job.Warn(action, $"KRL {what}s are written in {krlUnit} with 6 decimals; {Num.G(value)} {unit} would be 0 and was raised to {NumAppend.Format(KrlFormat.MinRate, 6)} {krlUnit}.");
        }
    }

    private void EmitRestoredSettings(RobotAction action, RobotCursor c)
    {
        bool wrote = false;
        if (c.SettingsBeforeLastPop is Settings before)
        {
            if (before.Speed != c.Speed)
            {
                Code(VelocityLine(c.Speed), action);
                wrote = true;
            }
            if (before.Acceleration != c.Acceleration)
            {
                Code(AccelerationLine(c.Acceleration), action);
                wrote = true;
            }
            if (before.Precision != c.Precision)
            {
                Code(PrecisionLine(c.Precision), action);
                wrote = true;
            }
        }
        if (!wrote)
        {
            _notes.NoCode(action);
        }
    }

    private void EmitCartesian(RobotAction action, RobotCursor c)
    {
        if (c.Position is not Vector position || c.Rotation is not Rotation rotation)
        {
            _notes.Error(action, "the target pose is not known, so no motion can be written.");
            return;
        }
        bool ptp = c.MotionType == MotionType.Joint;
        if (ptp)
        {
            WarnPtpSpeedOnce(action);
        }
        KukaConfiguration? config = StatusTurn(c, position, rotation);
        if (TryWriteInlineMove(ptp, position, rotation, c.ExternalAxesCartesian, config, c.Precision, action))
        {
            return;
        }
        StringBuilder line = BeginLine().Append(ptp ? "PTP " : "LIN ");
        AppendPoseTarget(line, position, rotation, c.ExternalAxesCartesian, config);
        EndLine(line.Append(Approximation(ptp, c.Precision)), action);
    }

    // A description that is not written as bytes, as characters (TryWriteDescription), narrowed into the line.
    private readonly char[] _description = new char[RobotAction.MaxWrittenDescriptionChars];

    /// <summary>
    /// Writes a <c>LIN</c>/<c>PTP</c> line with an inline target as <see cref="AppendPoseTarget"/> and <see cref="EndLine"/> write
    /// it, as ASCII bytes straight into the file's room (<see cref="LineSink.BeginAscii"/>) instead of through a builder: the
    /// position's three numbers, the kept text after them (orientation, Status and Turn, external axes), the approximation and
    /// the move's description. False (nothing written) with declared targets, a coordinate too large for the fast digits, or a
    /// description that is not digits and fixed words in ASCII; the caller then writes the line the general way.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private bool TryWriteInlineMove(bool ptp, Vector position, Rotation rotation, ExternalAxes? external, KukaConfiguration? config,
                                    double precision, RobotAction action)
    {
        if (!_inline)
        {
            return false;
        }
        PoseTail(rotation, external, config); // makes the kept text after the position, and its bytes, current
        if (_poseTailAsciiLength < 0)
        {
            return false;
        }
        ReadOnlySpan<byte> tail = _poseTailAscii.AsSpan(0, _poseTailAsciiLength);
        Span<byte> line = _src.BeginAscii(32 + 3 * (NumAppend.MaxChars + 4) + tail.Length + RobotAction.MaxWrittenDescriptionChars + 16);
        int at = Put(line, 0, ptp ? "  PTP {E6POS: X "u8 : "  LIN {E6POS: X "u8);
        if ((at = PutMm(line, at, position.X)) < 0 || (at = PutMm(line, Put(line, at, ", Y "u8), position.Y)) < 0
            || (at = PutMm(line, Put(line, at, ", Z "u8), position.Z)) < 0)
        {
            return false;
        }
        tail.CopyTo(line[at..]);
        at += tail.Length;
        line[at++] = (byte)'}';
        if (precision > 0)
        {
            at = Put(line, at, ptp ? " C_PTP"u8 : " C_DIS"u8); // Approximation's text
        }
        if (_human && (at = AsciiNarrow.TryWriteDescription(line, at, "  ; ["u8, action, _description)) < 0)
        {
            return false;
        }
        _src.EndAscii(at);
        return true;
    }

    private static int Put(Span<char> line, int at, ReadOnlySpan<char> text)
    {
        text.CopyTo(line[at..]);
        return at + text.Length;
    }

    private static int Put(Span<byte> line, int at, ReadOnlySpan<byte> text)
    {
        text.CopyTo(line[at..]);
        return at + text.Length;
    }

    /// <summary>Writes millimetres with 3 decimals as <see cref="KrlFormat.AppendPosition"/> does; −1 when too large for the fast digits.</summary>
    private static int PutMm(Span<byte> line, int at, double value)
    {
        int written = NumAppend.TryWriteScaledAscii(line[at..], value, 3);
        return written < 0 ? -1 : at + written;
    }

    private void EmitArc(RobotAction action, RobotCursor c)
    {
        if (c.Position is not Vector end || c.Rotation is not Rotation endRotation || c.ArcThrough is not Vector through)
        {
            _notes.Error(action, "the arc's points are not known, so no motion can be written.");
            return;
        }
        StringBuilder line = BeginLine().Append("CIRC ");
        AppendPoseTarget(line, through, c.ArcThroughRotation ?? endRotation, c.ExternalAxesCartesian);
        AppendPoseTarget(line.Append(", "), end, endRotation, c.ExternalAxesCartesian, StatusTurn(c, end, endRotation));
        EndLine(line.Append(Approximation(false, c.Precision)), action);
    }

    private void EmitAxes(RobotAction action, RobotCursor c)
    {
        if (c.Axes is not Joints joints)
        {
            _notes.Error(action, "the joint target is not known, so no motion can be written.");
            return;
        }
        WarnPtpSpeedOnce(action);
        ExternalAxes? external = c.ExternalAxesJoints;
        string type = KrlFormat.HasExternal(external) ? "E6AXIS" : "AXIS";
        StringBuilder line = BeginLine().Append("PTP ");
        KrlFormat.AppendAxes(BeginTarget(line, type), joints, external);
        EndTarget(line);
        EndLine(line.Append(Approximation(true, c.Precision)), action);
    }

    private void EmitAttach(RobotAction action, RobotCursor c)
    {
        if (c.Tool is not Tool tool)
        {
            _notes.Error(action, "no tool is attached after this action.");
            return;
        }
        _job.Warn(action, $"the weight and centre of gravity of tool \"{tool.Name}\" are not sent; set its load data on the controller.");
        _src.Add(Indent + $"; WARNING: set the load data (weight {Num.G(tool.Weight)} kg) of tool \"{tool.Name}\" on the controller.");
        Code("$TOOL = " + KrlFormat.ToolFrame(tool), action);
    }

    /// <summary>
    /// WAIT FOR on the input; with a time limit, timer 15 counts the wait ($TIMER in ms, started by $TIMER_STOP = FALSE) and
    /// an input still not reached when it passes the limit HALTs the program.
    /// </summary>
    private void EmitWaitDigital(ActionWaitDigital wait)
    {
        string input;
        if (IOPin.TryNumber(wait.PinName, out int number))
        {
            if (wait.IsToolPin)
            {
                _notes.Error(wait, "KUKA controllers have no separate tool inputs; declare a SIGNAL for it in $config.dat and use its name.");
                return;
            }
            if (number < 1 || number > 4096)
            {
                _notes.Error(wait, $"$IN inputs are numbered 1 to 4096, so input {Num.I(number)} does not exist.");
                return;
            }
            input = "$IN[" + Num.I(number) + "]";
        }
        else if (KrlText.IsValidName(wait.PinName))
        {
            input = wait.PinName;
        }
        else
        {
            _notes.Error(wait, $"\"{wait.PinName}\" is neither an input number nor a valid KRL signal name (letters, digits and '_', at most 24 characters).");
            return;
        }
        string reached = (wait.On ? "" : "NOT ") + input;
        if (wait.TimeoutMillis == 0)
        {
            Code("WAIT FOR " + reached, wait);
            return;
        }
        string timer = "$TIMER[" + Num.I(WaitTimer) + "]";
        Code(timer + " = 0", wait);
        _src.Add(Indent + "$TIMER_STOP[" + Num.I(WaitTimer) + "] = FALSE");
        _src.Add(Indent + "WAIT FOR " + reached + " OR (" + timer + " >= " + Num.I(wait.TimeoutMillis) + ")");
        _src.Add(Indent + "$TIMER_STOP[" + Num.I(WaitTimer) + "] = TRUE");
        _src.Add(Indent + "IF " + (wait.On ? "NOT " : "") + input + " THEN");
        _src.Add(Indent + "  HALT ; " + KrlText.Comment(wait.Describe()) + ": timed out");
        _src.Add(Indent + "ENDIF");
    }

    /// <summary>machina_di = $IN[n] (or a SIGNAL's name), machina_ai = $ANIN[n]: the program's variables declared at its start.</summary>
    private void EmitRead(ActionReadInput read)
    {
        string array = read.IsAnalog ? "$ANIN" : "$IN";
        int count = read.IsAnalog ? KukaActionEncoder.AnalogOutputs : KukaActionEncoder.DigitalOutputs;
        string variable = read.IsAnalog ? "machina_ai = " : "machina_di = ";
        if (IOPin.TryNumber(read.PinName, out int number))
        {
            if (read.IsToolPin)
            {
                _notes.Error(read, "KUKA controllers have no separate tool inputs; declare a SIGNAL for it in $config.dat and use its name.");
            }
            else if (number < 1 || number > count)
            {
                _notes.Error(read, $"{array} inputs are numbered 1 to {Num.I(count)}, so input {Num.I(number)} does not exist.");
            }
            else
            {
                Code(variable + array + "[" + Num.I(number) + "]", read);
            }
        }
        else if (KrlText.IsValidName(read.PinName))
        {
            Code(variable + read.PinName, read);
        }
        else
        {
            _notes.Error(read, $"\"{read.PinName}\" is neither an input number nor a valid KRL signal name (letters, digits and '_', at most 24 characters).");
        }
    }

    /// <summary>The timer a wait with a time limit uses (the driver's monitor uses 16).</summary>
    internal const int WaitTimer = 15;

    private void EmitOutput(RobotAction action, string pin, bool toolPin, string value, string array, int count)
    {
        if (IOPin.TryNumber(pin, out int number))
        {
            if (toolPin)
            {
                _notes.Error(action, $"KUKA controllers have no separate tool outputs; declare a SIGNAL for it in $config.dat and use its name.");
            }
            else if (number < 1 || number > count)
            {
                _notes.Error(action, $"{array} outputs are numbered 1 to {Num.I(count)}, so output {Num.I(number)} does not exist.");
            }
            else
            {
                Code(array + "[" + Num.I(number) + "] = " + value, action);
            }
        }
        else if (KrlText.IsValidName(pin))
        {
            // A named output is a SIGNAL declared on the controller (in $config.dat), e.g. SIGNAL DO_Gripper $OUT[5].
            Code(pin + " = " + value, action);
        }
        else
        {
            _notes.Error(action, $"\"{pin}\" is neither an output number nor a valid KRL signal name (letters, digits and '_', at most 24 characters).");
        }
    }

    private void WarnPtpSpeedOnce(RobotAction action)
    {
        if (_ptpSpeedWarned)
        {
            return;
        }
        _ptpSpeedWarned = true;
        const string reason = "joint (PTP) motions run at the controller's axis speeds ($VEL_AXIS, set by BAS #INITMOV); the Machina speed sets $VEL.CP for LIN and CIRC motions only.";
        _job.Warn(action, reason);
        _src.Add(Indent + "; WARNING: " + reason);
    }

    private static string Approximation(bool ptp, double precision) => precision > 0 ? (ptp ? " C_PTP" : " C_DIS") : "";

    /// <summary>
    /// Status and Turn of the target <paramref name="position"/>, <paramref name="rotation"/> as written (3 decimals) when a KUKA
    /// model is set and the cursor's joints are known, else null. The controller solves the written pose and takes the axis
    /// position with these S and T: with an axis near 0° (or A5 near the wrist singularity) the rounding can carry it to the other
    /// sign, so S and T are those of the written pose's solution nearest the cursor's joints, not of the joints themselves.
    /// </summary>
    private KukaConfiguration? StatusTurn(RobotCursor c, Vector position, Rotation rotation)
    {
        if (_job.Model is not { Brand: "KUKA" } model || c.Axes is not Joints joints)
        {
            return null;
        }
        if (!NearZero(joints))
        {
            return KukaConfiguration.From(model, joints);
        }
        (double a, double b, double cc) = KrlFormat.Abc(rotation);
        var written = new Vector(Written(position.X), Written(position.Y), Written(position.Z));
        Rotation writtenRotation = KrlFormat.FromAbc(Written(KrlFormat.Degrees(a)), Written(b), Written(cc));
        Joints solved = model.Kinematics.Closest(c.FlangePose(written, writtenRotation), joints) ?? joints;
        return KukaConfiguration.From(model, solved);
    }

    /// <summary>How close to 0° an axis must be for the rounding of the written pose to possibly change its sign, degrees.</summary>
    private const double RoundingReachDegrees = 1;

    private static bool NearZero(Joints joints)
    {
        for (int i = 0; i < Joints.Count; i++)
        {
            if (Math.Abs(joints[i]) < RoundingReachDegrees)
            {
                return true;
            }
        }
        return false;
    }

    /// <summary>A value (mm or degrees) as the target's text carries it: 3 decimals.</summary>
    private static double Written(double value) => Math.Round(value, 3);

    private void AppendPoseTarget(StringBuilder line, Vector position, Rotation rotation, ExternalAxes? external, KukaConfiguration? config = null)
    {
        ReadOnlySpan<char> tail = PoseTail(rotation, external, config);
        StringBuilder target = BeginTarget(line, "E6POS");
        KrlFormat.AppendPosition(target, position);
        target.Append(tail);
        EndTarget(line);
    }

    /// <summary>The target's text after its position (<see cref="KrlFormat.AppendOrientation"/>), kept while its values stay the same.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private ReadOnlySpan<char> PoseTail(Rotation rotation, ExternalAxes? external, KukaConfiguration? config)
    {
        if (!_tailKnown || rotation != _tailRotation || external != _tailExternal || config != _tailConfig)
        {
            // A toolpath keeps its orientation over many moves: its Euler angles are computed and written once, and the
            // text after the position (angles, Status and Turn, external axes) copied while they stay the same.
            WritePoseTail(rotation, external, config);
        }
        return _poseTail.AsSpan(0, _poseTailLength);
    }

    /// <summary>
    /// Writes <see cref="KrlFormat.AppendOrientation"/>'s text into the kept array: the three angles and Status and Turn straight
    /// into it (a path that turns on every move writes them on every move), through a builder only with external axes or an
    /// angle too large for the fast digits.
    /// </summary>
    private void WritePoseTail(Rotation rotation, ExternalAxes? external, KukaConfiguration? config)
    {
        (double a, double b, double c) = KrlFormat.Abc(rotation);
        (_tailKnown, _tailRotation, _tailExternal, _tailConfig) = (true, rotation, external, config);
        if (!KrlFormat.HasExternal(external))
        {
            Span<char> text = _poseTail;
            int at = PutAngle(text, Put(text, 0, ", A "), a);
            at = at < 0 ? -1 : PutAngle(text, Put(text, at, ", B "), b);
            at = at < 0 ? -1 : PutAngle(text, Put(text, at, ", C "), c);
            if (at >= 0)
            {
                if (config is KukaConfiguration st)
                {
                    at = Put(text, Put(text, Put(text, Put(text, at, ", S "), st.StatusText), ", T "), st.TurnText);
                }
                _poseTailLength = at;
                KeepAscii();
                return;
            }
        }
        StringBuilder sb = _poseTailText.Clear();
        KrlFormat.AppendOrientation(sb, (a, b, c), external, config);
        if (_poseTail.Length < sb.Length)
        {
            _poseTail = new char[sb.Length * 2];
        }
        sb.CopyTo(0, _poseTail, sb.Length);
        _poseTailLength = sb.Length;
        KeepAscii();
    }

    /// <summary>The kept text's bytes for the lines written as bytes; −1 as their length when it is not all ASCII.</summary>
    private void KeepAscii()
    {
        if (_poseTailAscii.Length < _poseTailLength)
        {
            _poseTailAscii = new byte[_poseTail.Length];
        }
        _poseTailAsciiLength = AsciiNarrow.TryWrite(_poseTail.AsSpan(0, _poseTailLength), _poseTailAscii);
    }

    /// <summary>Writes an angle as <see cref="KrlFormat.AppendOrientation"/> does (3 decimals, −180 as 180); −1 when too large for the fast digits.</summary>
    private static int PutAngle(Span<char> line, int at, double degrees)
    {
        int written = NumAppend.TryWriteScaled(line[at..], KrlFormat.Degrees(degrees), 3);
        return written < 0 ? -1 : at + written;
    }

    private readonly StringBuilder _poseTailText = new(96);
    private char[] _poseTail = new char[3 * (NumAppend.MaxChars + 4) + 64];
    private int _poseTailLength;
    private byte[] _poseTailAscii = new byte[3 * (NumAppend.MaxChars + 4) + 64];
    private int _poseTailAsciiLength;
    private bool _tailKnown;
    private Rotation _tailRotation;
    private ExternalAxes? _tailExternal;
    private KukaConfiguration? _tailConfig;

    /// <summary>Where a target's values go: straight into the line (inline), or into a declaration for the .dat file.</summary>
    private StringBuilder BeginTarget(StringBuilder line, string type)
    {
        if (_inline)
        {
            return line.Append('{').Append(type).Append(": ");
        }
        _declaration.Clear().Append("DECL ").Append(type).Append(" target").AppendFixed(++_targetCount, 0);
        return _declaration.Append("={");
    }

    private void EndTarget(StringBuilder line)
    {
        if (_inline)
        {
            line.Append('}');
            return;
        }
        _dat!.Add(_declaration.Append('}'));
        line.Append("target").AppendFixed(_targetCount, 0);
    }

    private StringBuilder BeginLine() => _line.Clear().Append(Indent);

    private void EndLine(StringBuilder line, RobotAction action)
    {
        if (_human)
        {
            line.Append("  ; [").AppendDescription(action, oneLine: true).Append(']');
        }
        _src.Add(line);
    }

    private void Code(string code, RobotAction action) => EndLine(BeginLine().Append(code), action);
}

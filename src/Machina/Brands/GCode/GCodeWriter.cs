using System.Text;

namespace Machina;

/// <summary>
/// Writes one G-code file from the state after each action (never re-deriving it). Keeps only what the printer is known to
/// hold: the feed rate last sent and the filament length at the last extruder reset (<c>G92 E0</c>).
/// </summary>
internal sealed class GCodeWriter
{
    /// <summary>Largest distance, mm, between an arc and the straight segments that replace it.</summary>
    internal const double ArcTolerance = 0.01;

    /// <summary>Height, mm, kept above the highest point the nozzle reached before it travels away at the start or end of a print.</summary>
    internal const double ClearanceMm = 10;

    /// <summary>Feed rate, mm/min, of the rise above the print (the original ZMorph ending's 300).</summary>
    private const double RiseFeed = 300;

    private readonly GCodeCompiler _compiler;
    private readonly GCodeFlavor _flavor;
    private readonly CompileJob _job;
    private readonly LineNotes _notes;
    private readonly ProgramOutput _output;
    private readonly bool _human;
    private readonly StringBuilder _sb = new(96);
    private WarningRuns _file = null!;
    private double _extrusionOrigin;
    private double _feed = double.NaN;
    private double _highest = double.NegativeInfinity;

    internal GCodeWriter(GCodeCompiler compiler, CompileJob job, ProgramOutput output)
    {
        _compiler = compiler;
        _flavor = compiler.Flavor;
        _job = job;
        _notes = new LineNotes(job, ProgramNotes.Semicolon, "", () => _file, Code);
        _output = output;
        _human = job.Options.HumanComments;
    }

    /// <summary>Writes the whole file.</summary>
    internal void Write()
    {
        // The preamble sets the extruder position to 0 at the filament length the program starts with.
        _extrusionOrigin = _job.NewCursor().ExtrudedLength;
        _file = new WarningRuns(_output.OpenFile(_job.ProgramName, "gcode", RobotProgram.Ascii, _compiler.CommentPrefix), "; ");
        _file.AddRange(_compiler.Header(_job));
        _file.Add("");
        _file.AddRange(_flavor.Preamble);
        _file.AddRange(_job.CustomDeclarations);
        _file.Add("");
        _job.Replay(EmitAction);
        _file.EndRun();
    }

    private void EmitAction(RobotAction action, RobotCursor c)
    {
        switch (action)
        {
            case ActionSpeed:
                if (Math.Round(c.Speed * 60, 3) < MinRate)
                {
                    Warning(action, $"feed rates are written in mm/min with 3 decimals; {Num.G(c.Speed)} mm/s would be F0 and was raised to F{NumAppend.Format(MinRate, 3)}.");
                }
                if (_flavor.FeedOnMotionLine)
                {
                    _notes.NoCode(action);
                }
                else
                {
                    _feed = Feed(c.Speed);
                    Code("G1 F" + Rate(_feed), action);
                }
                break;
            case ActionAcceleration:
                EmitAcceleration(action, c.Acceleration);
                break;
            case ActionPushPop { Push: false }:
                EmitRestoredSettings(action, c);
                break;
            case ActionTranslation or ActionTransformation:
                EmitLinear(action, c);
                break;
            case ActionArcMotion:
                EmitArc(action, c);
                break;
            case ActionWait wait:
                Code("G4 P" + Num.I(wait.Millis), action);
                break;
            case ActionMessage message:
                string text = GCodeText.Message(message.Message);
                if (text != message.Message)
                {
                    _job.Warn(action, "G-code messages cannot hold line breaks, control characters, ';', '(', ')' or '*'; they were replaced (';' by ',', brackets for parentheses, '*' by '+', others by spaces).");
                }
                Code(_flavor.MessageLine(text), action);
                break;
            case ActionComment comment:
                _file.Add("; " + GCodeText.Comment(comment.Comment));
                break;
            case ActionCustomCode { IsDeclaration: false } custom:
                Code(custom.Statement, action);
                break;
            case ActionIODigital digital:
                EmitOutput(action, digital.PinName, digital.IsToolPin, digital.On ? _flavor.DigitalOnValue : "0");
                break;
            case ActionIOAnalog analog:
                EmitAnalog(action, analog);
                break;
            case ActionTemperature temperature:
                EmitTemperature(action, temperature, c);
                break;
            case ActionInitialization init:
                EmitSequence(action, init.Initialize, c);
                break;
            case ActionMotionMode { MotionType: MotionType.Joint }:
                NotApplicable(action, "a 3D printer always moves in straight lines; joint motion does not apply.");
                break;
            case ActionPushPop or ActionMotionMode or ActionCoordinates or ActionExtrusion or ActionExtrusionRate or ActionDefineTool or ActionCustomCode:
                // Custom declarations are written at the top of the file.
                _notes.NoCode(action);
                break;
            case ActionRotation:
                NotApplicable(action, "a 3D printer cannot turn its tool.");
                break;
            case ActionWaitDigital:
                NotApplicable(action, "Machina's G-code programs do not wait for inputs.");
                break;
            case ActionReadInput:
                NotApplicable(action, "Machina's G-code programs do not read inputs.");
                break;
            case ActionAxes:
                NotApplicable(action, "a 3D printer has no robot joints to move.");
                break;
            case ActionPrecision:
                NotApplicable(action, "a 3D printer follows its path exactly and has no blend radius.");
                break;
            case ActionAttachTool or ActionDetachTool:
                NotApplicable(action, "a 3D printer has no tool frame; motions keep the tool-tip positions Machina computed.");
                break;
            case ActionExternalAxis or ActionArmAngle:
                NotApplicable(action, "a 3D printer has no external axes or arm angle.");
                break;
            default:
                throw ActionKinds.Unhandled(action, "The G-code writer");
        }
    }

    private void EmitAcceleration(RobotAction action, double acceleration)
    {
        if (!_flavor.SupportsAcceleration)
        {
            NotApplicable(action, "this printer's acceleration is set in its firmware.");
        }
        else if (acceleration == 0)
        {
            _notes.Error(action, "acceleration 0 means the device's default, which G-code cannot restore; the printer keeps its current acceleration.");
        }
        else
        {
            if (Math.Round(acceleration, 3) < MinRate)
            {
                Warning(action, $"accelerations are written in mm/s^2 with 3 decimals; {Num.G(acceleration)} mm/s^2 would be 0 and was raised to {NumAppend.Format(MinRate, 3)}.");
            }
            string a = Rate(acceleration);
            Code("M204 P" + a + " T" + a, action);
        }
    }

    private void EmitRestoredSettings(RobotAction action, RobotCursor c)
    {
        bool wrote = false;
        if (c.SettingsBeforeLastPop is Settings before)
        {
            if (before.Speed != c.Speed && !_flavor.FeedOnMotionLine)
            {
                _feed = Feed(c.Speed);
                Code("G1 F" + Rate(_feed), action);
                wrote = true;
            }
            if (before.Acceleration != c.Acceleration && _flavor.SupportsAcceleration)
            {
                EmitAcceleration(action, c.Acceleration);
                wrote = true;
            }
        }
        if (!wrote)
        {
            _notes.NoCode(action);
        }
    }

    private void EmitLinear(RobotAction action, RobotCursor c)
    {
        if (c.Position is not Vector position)
        {
            _notes.Error(action, "the target position is not known, so no motion can be written.");
            return;
        }
        WarnIfTurned(action, c);
        bool extrude = c.IsExtruding;
        if (extrude && c.LastPathLength is null)
        {
            MotionWarning(action, "unknown length", "this motion does not extrude: its length is unknown because the position before it was unknown.");
            extrude = false;
        }
        _file.Motion();
        double? e = extrude ? ExtruderPosition(c.PrevExtrudedLength, c.ExtrudedLength) : null;
        Motion(extrude ? "G1" : _flavor.TravelCode, position, e, c.Speed, action);
    }

    private void EmitArc(RobotAction action, RobotCursor c)
    {
        if (c.PrevPosition is not Vector start || c.Position is not Vector end || c.ArcThrough is not Vector through
            || !CircleArc.TryCreate(start, through, end, out CircleArc arc))
        {
            _notes.Error(action, "the arc's points are not known or do not define a circle, so no motion can be written.");
            return;
        }
        WarnIfTurned(action, c);
        _file.Motion();
        bool extrude = c.IsExtruding;
        string code = extrude ? "G1" : _flavor.TravelCode;
        double before = c.PrevExtrudedLength, total = c.ExtrudedLength - before;
        Vector normal = arc.Normal;
        if (_flavor.SupportsArcs && Math.Abs(normal.Z) > 1 - 1e-9 && Math.Abs(end.Z - start.Z) < 1e-9)
        {
            // Seen from above, counter-clockwise is G3 and clockwise G2; I and J locate the centre from the start.
            double? e = extrude ? ExtruderPosition(before, c.ExtrudedLength) : null;
            Vector toCenter = arc.Center - start;
            Motion(normal.Z > 0 ? "G3" : "G2", end, e, c.Speed, action, toCenter);
            return;
        }
        int segments = arc.SegmentCount(ArcTolerance);
        for (int k = 1; k <= segments; k++)
        {
            double fraction = (double)k / segments;
            Vector point = k == segments ? end : arc.PointAt(fraction);
            double? e = extrude ? ExtruderPosition(before + total * (k - 1) / segments, before + total * fraction) : null;
            Motion(code, point, e, c.Speed, k == segments ? action : null);
        }
    }

    /// <summary>The E value for a motion that brings the filament length from <paramref name="before"/> to <paramref name="after"/>, resetting the extruder first when the flavour asks.</summary>
    private double ExtruderPosition(double before, double after)
    {
        double e = after - _extrusionOrigin;
        double sent = before - _extrusionOrigin;
        if (e > _flavor.ExtrusionResetLimit && sent > 0)
        {
            _file.Add("; Homing extrusion length after " + NumAppend.Format(sent, 5) + " mm (" + Num.G(_flavor.ExtrusionResetLimit) + " mm limit)");
            _file.Add("G92 E0.0000");
            _extrusionOrigin = before;
            e = after - _extrusionOrigin;
        }
        return e;
    }

    private void Motion(string code, Vector point, double? e, double speed, RobotAction? action, Vector? arcCenterOffset = null)
    {
        double feed = Feed(speed);
        if (!_flavor.FeedOnMotionLine && feed != _feed)
        {
            _file.Add("G1 F" + Rate(feed));
            _feed = feed;
        }
        _highest = Math.Max(_highest, point.Z);
        if (arcCenterOffset is null && TryWriteMotion(code, point, e, feed, action))
        {
            return;
        }
        StringBuilder sb = _sb.Clear();
        sb.Append(code).Append(" X").AppendFixed(point.X, 3);
        sb.Append(" Y").AppendFixed(point.Y, 3);
        sb.Append(" Z").AppendFixed(point.Z, 3);
        if (arcCenterOffset is Vector ij)
        {
            sb.Append(" I").AppendFixed(ij.X, 3);
            sb.Append(" J").AppendFixed(ij.Y, 3);
        }
        if (e is double extruder)
        {
            sb.Append(" E").AppendFixed(extruder, 5);
        }
        if (_flavor.FeedOnMotionLine && feed != _feed)
        {
            sb.Append(" F").Append(Rate(feed));
            _feed = feed;
        }
        if (action is not null && _human)
        {
            sb.Append("  ; [").AppendDescription(action, oneLine: true).Append(']');
        }
        _file.Add(sb);
    }

    /// <summary>
    /// Writes <see cref="Motion"/>'s line of a straight motion as ASCII bytes straight into the file's room
    /// (<see cref="LineSink.BeginAscii"/>) instead of through the builder; false (nothing written) when a number is too large for
    /// the fast digits or a text is not ASCII, and the caller writes the line through its builder.
    /// </summary>
    private bool TryWriteMotion(string code, Vector point, double? e, double feed, RobotAction? action)
    {
        bool describe = action is not null && _human;
        bool feedHere = _flavor.FeedOnMotionLine && feed != _feed;
        string rate = feedHere ? Rate(feed) : "";
        Span<byte> line = _file.BeginAscii(code.Length + rate.Length + 5 * (NumAppend.MaxChars + 3) + (describe ? RobotAction.MaxWrittenDescriptionChars : 0) + 8);
        int at = AsciiNarrow.TryWrite(code, line);
        if (at < 0)
        {
            return false;
        }
        if ((at = PutNumber(line, Put(line, at, " X"u8), point.X, 3)) < 0 || (at = PutNumber(line, Put(line, at, " Y"u8), point.Y, 3)) < 0
            || (at = PutNumber(line, Put(line, at, " Z"u8), point.Z, 3)) < 0
            || (e is double extruder && (at = PutNumber(line, Put(line, at, " E"u8), extruder, 5)) < 0))
        {
            return false;
        }
        if (feedHere)
        {
            int written = AsciiNarrow.TryWrite(rate, line[(at + 2)..]);
            if (written < 0)
            {
                return false;
            }
            at = Put(line, at, " F"u8) + written;
        }
        if (describe && (at = AsciiNarrow.TryWriteDescription(line, at, "  ; ["u8, action!, _description)) < 0)
        {
            return false;
        }
        _file.EndAscii(at);
        if (feedHere)
        {
            _feed = feed;
        }
        return true;
    }

    /// <summary>Writes a number as <see cref="NumAppend.AppendFixed"/> does; −1 when it is too large for the fast digits.</summary>
    private static int PutNumber(Span<byte> line, int at, double value, int decimals)
    {
        int written = NumAppend.TryWriteScaledAscii(line[at..], value, decimals);
        return written < 0 ? -1 : at + written;
    }

    /// <summary>A speed in mm/s as a feed rate in mm/min (speeds are at most 1,000,000 mm/s, so the feed always fits).</summary>
    private static double Feed(double mmPerSecond) => mmPerSecond * 60;

    /// <summary>The smallest feed rate (mm/min) or acceleration (mm/s²) written: a value above 0 that would print as 0 is raised to it.</summary>
    internal const double MinRate = 0.001;

    /// <summary>A feed rate or acceleration (above 0) with 3 decimals, at least <see cref="MinRate"/>, never in exponent form.</summary>
    private static string Rate(double value) => NumAppend.Format(Math.Max(Math.Round(value, 3), MinRate), 3);

    private void EmitOutput(RobotAction action, string pin, bool toolPin, string value)
    {
        if (toolPin)
        {
            _notes.Error(action, "a 3D printer has no separate tool outputs.");
        }
        else if (!IOPin.TryNumber(pin, out int number))
        {
            _notes.Error(action, $"G-code addresses outputs by pin number, and \"{pin}\" is not a number.");
        }
        else
        {
            Code("M42 P" + Num.I(number) + " S" + value, action);
        }
    }

    private void EmitAnalog(RobotAction action, ActionIOAnalog analog)
    {
        if (analog.Value < 0 || analog.Value > 255)
        {
            _notes.Error(action, $"printer outputs take values from 0 to 255, and {Num.G(analog.Value)} is outside that range.");
            return;
        }
        double rounded = Math.Round(analog.Value, MidpointRounding.AwayFromZero);
        if (rounded != analog.Value && !analog.IsToolPin && analog.IsDigit)
        {
            Warning(action, $"printer outputs take whole values from 0 to 255; {Num.G(analog.Value)} is rounded to {Num.G(rounded)}.");
        }
        EmitOutput(action, analog.PinName, analog.IsToolPin, Num.G(rounded));
    }

    private void EmitTemperature(RobotAction action, ActionTemperature temperature, RobotCursor c)
    {
        string code = temperature.Part switch
        {
            RobotPartType.Extruder => temperature.Wait ? "M109" : "M104",
            RobotPartType.Bed => temperature.Wait ? "M190" : "M140",
            _ => temperature.Wait ? "M191" : "M141",
        };
        Code(code + " S" + NumAppend.Format(c.Temperatures[(int)temperature.Part], 0), action);
    }

    private void EmitSequence(RobotAction action, bool start, RobotCursor c)
    {
        if (start)
        {
            // Homing after something was printed must not drag the nozzle through it: rise first.
            if (double.IsFinite(_highest))
            {
                _file.Add(RiseLine(_highest + ClearanceMm));
            }
            _file.AddRange(_flavor.StartSequence);
        }
        else
        {
            WriteEnd();
        }
        if (start || _flavor.EndResetsExtruder)
        {
            _extrusionOrigin = c.ExtrudedLength;
        }
        // The sequences may change the feed rate; send it again before the next motion.
        _feed = double.NaN;
        if (start && !_flavor.FeedOnMotionLine)
        {
            _feed = Feed(c.Speed);
            _file.Add("G1 F" + Rate(_feed));
        }
        _notes.NoCode(action);
    }

    /// <summary>
    /// The ending: retract, rise straight up above everything printed (plus <see cref="ClearanceMm"/>), travel to the park position
    /// at that height, then shut down.
    /// </summary>
    private void WriteEnd()
    {
        _file.AddRange(_flavor.EndRetract);
        double rise = Math.Max(_flavor.ParkMinZ, _highest + ClearanceMm);
        if (double.IsFinite(rise))
        {
            _file.Add(RiseLine(rise));
            _highest = Math.Max(_highest, rise);
        }
        if (_flavor.ParkXY is (double x, double y))
        {
            StringBuilder sb = _sb.Clear().Append(_flavor.TravelCode).Append(" X");
            sb.AppendFixed(x, 3).Append(" Y");
            _file.Add(sb.AppendFixed(y, 3));
        }
        _file.AddRange(_flavor.EndShutdown);
    }

    private string RiseLine(double z)
    {
        StringBuilder sb = _sb.Clear().Append(_flavor.TravelCode).Append(" Z");
        sb.AppendFixed(z, 3).Append(" F");
        return sb.AppendFixed(RiseFeed, 3).ToString();
    }

    private void WarnIfTurned(RobotAction action, RobotCursor c)
    {
        if (c.PrevRotation is Rotation before && c.Rotation is Rotation after && !after.IsSimilar(before, 1e-6))
        {
            MotionWarning(action, "turned", "a 3D printer cannot turn its tool; the change of orientation is ignored.");
        }
    }

    /// <summary>
    /// An action a printer cannot do: a warning, and the note <c>; ACTION "…" NOT APPLICABLE TO THIS DEVICE</c> as its line
    /// (the same text as <see cref="LineNotes.NotApplicable"/> with <see cref="Code"/>), its description written straight into
    /// the line: a toolpath that turns on every other move (10^6-line files) made five strings per turn.
    /// </summary>
    private void NotApplicable(RobotAction action, string reason)
    {
        _job.Warn(action, reason);
        // The description is found once and written twice (a toolpath that turns on every other move wrote it twice per
        // turn); a move's or a turn's (digits and fixed words) without a string, as AppendDescription writes it, into a kept
        // array (a buffer on the stack was cleared on every turn).
        int written = action.TryWriteDescription(_description);
        ReadOnlySpan<char> description = written >= 0 ? _description.AsSpan(0, written) : ProgramText.OneLine(action.Describe());
        if (TryWriteNotApplicable(description))
        {
            return;
        }
        StringBuilder sb = _sb.Clear().Append("; ACTION \"").Append(description).Append("\" NOT APPLICABLE TO THIS DEVICE");
        if (_human)
        {
            sb.Append("  ; [").Append(description).Append(']');
        }
        _file.Add(sb);
    }

    private readonly char[] _description = new char[RobotAction.MaxWrittenDescriptionChars];

    /// <summary>
    /// Writes <see cref="NotApplicable"/>'s line as ASCII bytes straight into the file's room (<see cref="LineSink.BeginAscii"/>);
    /// false (nothing written) when the description is not all ASCII, and the caller writes the line through its builder.
    /// </summary>
    private bool TryWriteNotApplicable(ReadOnlySpan<char> description)
    {
        Span<byte> line = _file.BeginAscii(2 * description.Length + 48);
        int at = Put(line, 0, "; ACTION \""u8);
        int length = AsciiNarrow.TryWrite(description, line[at..]);
        if (length < 0)
        {
            return false;
        }
        int start = at;
        at = Put(line, at + length, "\" NOT APPLICABLE TO THIS DEVICE"u8);
        if (_human)
        {
            at = Put(line, at, "  ; ["u8);
            line.Slice(start, length).CopyTo(line[at..]);
            at += length;
            line[at++] = (byte)']';
        }
        _file.EndAscii(at);
        return true;
    }

    private static int Put(Span<byte> line, int at, ReadOnlySpan<byte> text)
    {
        text.CopyTo(line[at..]);
        return at + text.Length;
    }

    private void Code(string line, RobotAction action)
    {
        _file.Add(_human ? line + "  ; [" + GCodeText.Comment(action.Describe()) + "]" : line);
    }

    private void Warning(RobotAction action, string reason)
    {
        _job.Warn(action, reason);
        _file.Add("; WARNING: " + reason);
    }

    /// <summary>A warning of the motion about to be written: motions in a row with the same <paramref name="kind"/> share its comment (<see cref="WarningRuns"/>).</summary>
    private void MotionWarning(RobotAction action, string kind, string reason)
    {
        _job.Warn(action, reason);
        _file.Warn(kind, "; WARNING: " + reason);
    }
}

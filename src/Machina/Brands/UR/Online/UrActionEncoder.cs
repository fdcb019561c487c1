namespace Machina;

/// <summary>
/// Turns an issued action into the integers the UR driver reads (spec online §7.4), from the cursor state after the action.
/// Only the last instruction of an action carries its id; helpers carry id 0, so each action is acknowledged once. It is also
/// the one place that says what the driver can run: <see cref="WhyNot(RobotAction)"/> and <see cref="TryEncode"/> refuse, with
/// the reason, what it has no instruction for, what a UR does not have, and values its integers cannot carry or that would
/// stop the robot's program (a speed that rounds to 0).
/// </summary>
internal static class UrActionEncoder
{
    /// <summary>Most integers one action produces (an arc: id, code and two poses, 14; a pop of three settings: 3 × 3).</summary>
    public const int MaxValues = 16;

    /// <summary>
    /// Why the driver cannot run this kind of action, whatever the robot's state (a verb it has no instruction for, an output
    /// a UR does not have), or null. <see cref="TryEncode"/> asks it first.
    /// </summary>
    public static string? WhyNot(RobotAction action) => action switch
    {
        // What a UR controller cannot do online at all (docs/online.md, "What cannot be streamed").
        ActionExternalAxis => Cannot(action, "a UR arm has six joints and no external axes to move."),
        ActionArmAngle => Cannot(action, "UR arms have six joints and no arm angle (it exists only on 7-axis robots)."),
        ActionCustomCode => Cannot(action, "the driver cannot run URScript text sent while it runs: URScript has no eval, a script sent to the controller replaces the running program (the driver), and the driver does not use Interpreter Mode (software 5.10 and later); compile the program to include custom code."),
        ActionTemperature => Cannot(action, "a UR robot has no heaters to control."),
        ActionExtrusion or ActionExtrusionRate => Cannot(action, "a UR robot has no extruder; use IO to drive one."),
        ActionIODigital d when UrOutputs.WhyNot(d) is string problem => $"\"{action}\" cannot be streamed to a UR robot: {problem}",
        ActionIOAnalog a when UrOutputs.WhyNot(a) is string problem => $"\"{action}\" cannot be streamed to a UR robot: {problem}",
        ActionWaitDigital w when UrInputs.WhyNot(w) is string problem => $"\"{action}\" cannot be streamed to a UR robot: {problem}",
        ActionReadInput r when UrInputs.WhyNot(r) is string problem => $"\"{action}\" cannot be streamed to a UR robot: {problem}",
        _ => null,
    };

    private static string Cannot(RobotAction action, string why) => $"\"{action}\" cannot be streamed to a UR robot: {why}";

    /// <summary>
    /// Writes the instructions for <paramref name="action"/> into <paramref name="into"/> (<paramref name="count"/> integers, 0 =
    /// nothing to send) and returns null, or returns why the driver cannot run it and writes nothing usable.
    /// </summary>
    public static string? TryEncode(RobotAction action, RobotCursor after, Span<int> into, out int count)
    {
        count = 0;
        if (WhyNot(action) is string refusal)
        {
            return refusal;
        }
        var wire = new Wire(action);
        count = Encode(action, after, into, ref wire);
        return wire.Problem;
    }

    /// <summary>Writes the instructions for <paramref name="action"/> and returns how many integers (0 = nothing to send).</summary>
    /// <exception cref="InvalidOperationException">The driver cannot run it (issuing refuses such actions first).</exception>
    public static int Encode(RobotAction action, RobotCursor after, Span<int> into) =>
        TryEncode(action, after, into, out int count) is string problem ? throw new InvalidOperationException(problem) : count;

    private static int Encode(RobotAction action, RobotCursor after, Span<int> into, ref Wire wire)
    {
        int id = action.Id;
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                return Pose(into, id, after.MotionType == MotionType.Linear ? UrInstructionCode.MoveL : UrInstructionCode.MoveJPose,
                    Known(after.Position, action), Known(after.Rotation, action), ref wire);
            case ActionArcMotion:
                // The via pose and the target as the compiler's movec has them: the through point with its orientation, then the end.
                into[0] = id;
                into[1] = (int)UrInstructionCode.MoveC;
                PoseValues(into[2..], Known(after.ArcThrough, action), Known(after.ArcThroughRotation, action), ref wire);
                PoseValues(into[8..], Known(after.Position, action), Known(after.Rotation, action), ref wire);
                return 14;
            case ActionAxes:
                Joints j = Known(after.Axes, action);
                return Put(into, id, UrInstructionCode.MoveJJoints,
                    wire.Degrees(j.J1), wire.Degrees(j.J2), wire.Degrees(j.J3), wire.Degrees(j.J4), wire.Degrees(j.J5), wire.Degrees(j.J6));
            case ActionWait wait:
                return Put(into, id, UrInstructionCode.Sleep, wire.Scale(wait.Millis));
            case ActionSpeed:
                return Put(into, id, UrInstructionCode.AllSpeed, wire.Positive(after.Speed, "a speed", "mm/s"));
            case ActionAcceleration:
                return Put(into, id, UrInstructionCode.AllAcceleration, wire.Positive(after.Acceleration, "an acceleration", "mm/s²"));
            case ActionPrecision:
                return Put(into, id, UrInstructionCode.Blend, wire.Millimetres(after.Precision));
            case ActionDefineTool define:
                // Nothing is sent now, but a tool the wire cannot carry could never be attached: refused where it is defined.
                Tool(into, id, define.Tool.TcpPosition, define.Tool.TcpOrientation, define.Tool.Weight, ref wire);
                return 0;
            case ActionAttachTool:
                Tool tool = after.Tool ?? throw new InvalidOperationException($"No tool is attached after \"{action}\".");
                return Tool(into, id, tool.TcpPosition, tool.TcpOrientation, tool.Weight, ref wire);
            case ActionDetachTool:
                return Tool(into, id, Vector.Zero, Rotation.Identity, 0, ref wire);
            case ActionIODigital digital:
                return Put(into, id, UrInstructionCode.SetDigitalOut, digital.PinNumber, digital.On ? 1 : 0, digital.IsToolPin ? 1 : 0);
            case ActionIOAnalog analog:
                return Put(into, id, UrInstructionCode.SetAnalogOut, analog.PinNumber, wire.Scale(analog.Value * UrWire.FactorAnalog));
            case ActionReadInput r:
                return Put(into, id, r.IsAnalog ? UrInstructionCode.ReadAnalogIn : UrInstructionCode.ReadDigitalIn, r.PinNumber, r.IsToolPin ? 1 : 0);
            case ActionWaitDigital w:
                return Put(into, id, UrInstructionCode.WaitDigitalIn, w.PinNumber, w.On ? 1 : 0, w.IsToolPin ? 1 : 0, wire.Scale(w.TimeoutMillis));
            case ActionPushPop { Push: false }:
                return Pop(into, id, after, ref wire);
            default:
                // Message, Comment, MotionMode, Coordinates, Push, Initialization: nothing the robot does.
                return 0;
        }
    }

    private static int Pose(Span<int> into, int id, UrInstructionCode code, Vector p, Rotation r, ref Wire wire)
    {
        into[0] = id;
        into[1] = (int)code;
        PoseValues(into[2..], p, r, ref wire);
        return 8;
    }

    /// <summary>The six integers of a pose: X Y Z (0.001 mm) and the rotation vector RX RY RZ (1e-6 rad).</summary>
    private static void PoseValues(Span<int> into, Vector p, Rotation r, ref Wire wire)
    {
        RotationVector rv = r.ToRotationVector();
        (into[0], into[1], into[2]) = (wire.Millimetres(p.X), wire.Millimetres(p.Y), wire.Millimetres(p.Z));
        (into[3], into[4], into[5]) = (wire.Degrees(rv.X), wire.Degrees(rv.Y), wire.Degrees(rv.Z));
    }

    private static int Tool(Span<int> into, int id, Vector p, Rotation r, double kg, ref Wire wire)
    {
        int n = Pose(into, id, UrInstructionCode.SetTool, p, r, ref wire);
        into[n] = wire.Scale(kg * UrWire.FactorKilogram);
        return n + 1;
    }

    /// <summary>One instruction per setting the pop changed; only the last carries the id. Nothing when nothing changed.</summary>
    private static int Pop(Span<int> into, int id, RobotCursor after, ref Wire wire)
    {
        var before = after.SettingsBeforeLastPop ?? after.CurrentSettings;
        int n = 0;
        if (before.Speed != after.Speed)
        {
            n += Put(into[n..], 0, UrInstructionCode.AllSpeed, wire.Positive(after.Speed, "a speed", "mm/s"));
        }
        if (before.Acceleration != after.Acceleration)
        {
            n += Put(into[n..], 0, UrInstructionCode.AllAcceleration, wire.Positive(after.Acceleration, "an acceleration", "mm/s²"));
        }
        if (before.Precision != after.Precision)
        {
            n += Put(into[n..], 0, UrInstructionCode.Blend, wire.Millimetres(after.Precision));
        }
        if (n > 0)
        {
            into[n - 3] = id;
        }
        return n;
    }

    private static int Put(Span<int> into, int id, UrInstructionCode code, params ReadOnlySpan<int> values)
    {
        into[0] = id;
        into[1] = (int)code;
        values.CopyTo(into[2..]);
        return values.Length + 2;
    }

    private static T Known<T>(T? value, RobotAction action) where T : struct =>
        value ?? throw new InvalidOperationException($"\"{action}\" cannot be streamed: the robot's {typeof(T).Name.ToLowerInvariant()} is not known yet.");

    /// <summary>Scales values to the wire's integers and keeps the first problem met (then writes 0 in its place).</summary>
    private ref struct Wire(RobotAction action)
    {
        public string? Problem { get; private set; }

        public int Millimetres(double mm) => Scale(mm * UrScriptText.Mm * UrWire.FactorMetre);

        public int Degrees(double degrees) => Scale(degrees * UrScriptText.Rad * UrWire.FactorRadian);

        /// <summary>A speed or acceleration in mm units: at least one step of the wire (0.001 mm), or a problem (the driver would run it as 0).</summary>
        public int Positive(double mm, string what, string unit)
        {
            int value = Millimetres(mm);
            if (value <= 0 && Problem is null)
            {
                Problem = $"\"{Abbreviate(action.ToInstruction())}\" cannot be streamed to a UR robot: {what} of {Num.G(mm)} {unit} is 0 in its driver's {Num.G(MillimetreStep)} {unit} steps, and the robot would never get anywhere.";
            }
            return value;
        }

        public int Scale(double scaled)
        {
            if (double.IsFinite(scaled) && Math.Abs(scaled) < int.MaxValue)
            {
                return (int)Math.Round(scaled, MidpointRounding.AwayFromZero);
            }
            Problem ??= $"\"{Abbreviate(action.ToInstruction())}\" cannot be streamed to a UR robot: a value is beyond its driver's 32-bit numbers ({Limits}).";
            return 0;
        }

        /// <summary>One step of the wire in millimetres (0.001 mm).</summary>
        private static double MillimetreStep => 1 / (UrScriptText.Mm * UrWire.FactorMetre);

        /// <summary>What the wire carries at most, in the user's units.</summary>
        private static string Limits =>
            $"lengths and speeds up to ±{Num.G(Math.Floor(int.MaxValue / (UrScriptText.Mm * UrWire.FactorMetre)))} mm, angles ±{Num.G(Math.Floor(int.MaxValue / (UrScriptText.Rad * UrWire.FactorRadian)))}°, times {Num.G(Math.Floor(int.MaxValue / UrWire.FactorSecond))} s";

        private static string Abbreviate(string text) => text.Length <= 60 ? text : text[..57] + "...";
    }
}

namespace Machina;

/// <summary>
/// Turns an issued action into what Machina's KRL driver runs, reading every value from the cursor state after the action and
/// converting with the KRL compiler's conventions (<see cref="KrlFormat"/>: A, B, C of the tool frame, m/s, seconds). Actions the
/// driver cannot run are named by <see cref="WhyCannotStream"/> when they are issued, so nothing is ever silently skipped or
/// sent as null (fix of bug K1); the cursor is only read, never changed (fix of bug K3).
/// </summary>
internal static class KukaActionEncoder
{
    /// <summary>Highest digital output number of <c>$OUT</c>.</summary>
    public const int DigitalOutputs = 4096;

    /// <summary>Highest analog output number of <c>$ANOUT</c>.</summary>
    public const int AnalogOutputs = 32;

    /// <summary>Why the KRL driver cannot run <paramref name="action"/>, naming it, or null when it can (or when there is nothing to send).</summary>
    public static string? WhyCannotStream(RobotAction action) => action switch
    {
        ActionExternalAxis => Refuse(action, "the driver does not move external axes; compile the program offline for E1 to E6."),
        ActionArmAngle => Refuse(action, "KUKA arms of this kind have no arm angle to set."),
        ActionCustomCode => Refuse(action, "KRL cannot run text sent at run time: the controller compiles a program when it is selected, and EthernetKRL carries values into declared variables, never statements; compile the program offline to include custom code."),
        ActionTemperature or ActionExtrusion or ActionExtrusionRate =>
            Refuse(action, "a KUKA arm has no extruder or heated parts; this is for 3D printers."),
        ActionIODigital digital => WhyNotOutput(action, digital.PinName, digital.IsToolPin, DigitalOutputs, "$OUT"),
        ActionWaitDigital wait => WhyNotInput(action, wait.PinName, wait.IsToolPin, DigitalOutputs, "$IN"),
        ActionReadInput read => WhyNotInput(action, read.PinName, read.IsToolPin, read.IsAnalog ? AnalogOutputs : DigitalOutputs, read.IsAnalog ? "$ANIN" : "$IN"),
        ActionIOAnalog analog => WhyNotOutput(action, analog.PinName, analog.IsToolPin, AnalogOutputs, "$ANOUT")
            ?? (analog.Value is < -1 or > 1 ? Refuse(action, $"KRL analog outputs take values from -1 to 1, and {Num.G(analog.Value)} is outside that range.") : null),
        _ => null,
    };

    private static string? WhyNotInput(RobotAction action, string pin, bool toolPin, int count, string array)
    {
        if (toolPin)
        {
            return Refuse(action, "KUKA controllers have no separate tool inputs; use the number of the controller input wired to the tool.");
        }
        if (!IOPin.TryNumber(pin, out int number))
        {
            return Refuse(action, $"the driver reads inputs by number ({array}[1] to {array}[{Num.I(count)}]); a signal name such as \"{pin}\" exists only in the controller's configuration.");
        }
        return number < 1 || number > count ? Refuse(action, $"{array} inputs are numbered 1 to {Num.I(count)}, so input {Num.I(number)} does not exist.") : null;
    }

    private static string? WhyNotOutput(RobotAction action, string pin, bool toolPin, int count, string array)
    {
        if (toolPin)
        {
            return Refuse(action, "KUKA controllers have no separate tool outputs; use the number of the controller output wired to the tool.");
        }
        if (!IOPin.TryNumber(pin, out int number))
        {
            return Refuse(action, $"the driver sets outputs by number ({array}[1] to {array}[{Num.I(count)}]); a signal name such as \"{pin}\" exists only in the controller's configuration.");
        }
        return number < 1 || number > count ? Refuse(action, $"{array} outputs are numbered 1 to {Num.I(count)}, so output {Num.I(number)} does not exist.") : null;
    }

    /// <summary>The refusal of <paramref name="action"/> for the reason <paramref name="why"/>, naming the action.</summary>
    internal static string Refuse(RobotAction action, string why) => $"{action.Type} ({action.ToInstruction()}) is not supported online on KUKA: {why}";

    /// <summary>
    /// The driver instruction for <paramref name="action"/> with id <paramref name="id"/>, or null when it has nothing to send
    /// (push, define tool, motion mode, coordinates, comment, a pop that changed nothing).
    /// </summary>
    /// <exception cref="NotSupportedException">The action is one <see cref="WhyCannotStream"/> refuses.</exception>
    public static KukaInstruction? Encode(RobotAction action, int id, RobotCursor after)
    {
        ArgumentNullException.ThrowIfNull(action);
        ArgumentNullException.ThrowIfNull(after);
        if (WhyCannotStream(action) is string refusal)
        {
            throw new NotSupportedException(refusal);
        }
        var v = new KukaValues();
        KukaActionCode code;
        string text = "";
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                code = after.MotionType == MotionType.Joint ? KukaActionCode.JointToPose : KukaActionCode.Linear;
                SetFrame(ref v, Known(after.Position, action), Known(after.Rotation, action));
                break;
            case ActionArcMotion:
                // CIRC auxiliary, target: the points of the KRL compiler's CIRC (the auxiliary point's orientation as it writes it).
                code = KukaActionCode.Circular;
                Rotation end = Known(after.Rotation, action);
                SetFrame(ref v, Known(after.Position, action), end);
                SetFrame(ref v, Known(after.ArcThrough, action), after.ArcThroughRotation ?? end, KukaProtocol.ValueCount);
                break;
            case ActionAxes:
                code = KukaActionCode.JointToAxes;
                Joints joints = Known(after.Axes, action);
                for (int i = 0; i < Joints.Count; i++)
                {
                    v[i] = Math.Round(joints[i], 3);
                }
                break;
            case ActionSpeed:
                code = KukaActionCode.Speed;
                v[0] = KrlFormat.PerMetre(after.Speed);
                break;
            case ActionAcceleration:
                code = KukaActionCode.Acceleration;
                v[0] = Acceleration(after.Acceleration);
                break;
            case ActionPrecision:
                code = KukaActionCode.Precision;
                v[0] = Math.Round(after.Precision, 3);
                break;
            case ActionWait wait:
                code = KukaActionCode.Wait;
                v[0] = wait.Millis / 1000.0;
                break;
            case ActionMessage message:
                code = KukaActionCode.Message;
                text = MessageText(message.Message);
                break;
            case ActionAttachTool:
                code = KukaActionCode.AttachTool;
                Tool tool = after.Tool ?? throw new InvalidOperationException($"No tool is attached after \"{action}\".");
                SetFrame(ref v, tool.TcpPosition, tool.TcpOrientation);
                break;
            case ActionDetachTool:
                code = KukaActionCode.DetachTool;
                break;
            case ActionIODigital digital:
                code = KukaActionCode.DigitalOutput;
                v[0] = digital.PinNumber;
                v[1] = digital.On ? 1 : 0;
                break;
            case ActionWaitDigital wait:
                code = KukaActionCode.WaitInput;
                v[0] = wait.PinNumber;
                v[1] = wait.On ? 1 : 0;
                v[2] = wait.TimeoutMillis;
                break;
            case ActionReadInput read:
                code = read.IsAnalog ? KukaActionCode.ReadAnalog : KukaActionCode.ReadDigital;
                v[0] = read.PinNumber;
                break;
            case ActionIOAnalog analog:
                code = KukaActionCode.AnalogOutput;
                v[0] = analog.PinNumber;
                v[1] = Math.Round(analog.Value, 6);
                break;
            case ActionPushPop { Push: false }:
                if (after.SettingsBeforeLastPop is not Settings before || before.Speed == after.Speed && before.Acceleration == after.Acceleration && before.Precision == after.Precision)
                {
                    return null;
                }
                code = KukaActionCode.Settings;
                v[0] = KrlFormat.PerMetre(after.Speed);
                v[1] = Acceleration(after.Acceleration);
                v[2] = Math.Round(after.Precision, 3);
                break;
            default:
                // Push, DefineTool, MotionMode, Coordinates, Comment: they change only Machina's state. Initialize and Terminate:
                // a KUKA program needs no start-up or shut-down sequence (the KRL compiler writes a comment).
                return null;
        }
        return new KukaInstruction(id, code, v, text);
    }

    /// <summary>True when <see cref="MessageText"/> shortens <paramref name="message"/>.</summary>
    public static bool IsTruncated(string message) => message.Length > KukaProtocol.MaxTextLength;

    /// <summary>The text the driver shows: one line, at most <see cref="KukaProtocol.MaxTextLength"/> characters.</summary>
    public static string MessageText(string message)
    {
        string line = KrlText.Comment(message);
        return line.Length > KukaProtocol.MaxTextLength ? line[..KukaProtocol.MaxTextLength] : line;
    }

    private static double Acceleration(double mmPerSecond2) => Settings.MeansControllerAcceleration(mmPerSecond2) ? 0 : KrlFormat.PerMetre(mmPerSecond2);

    /// <summary>X, Y, Z (mm) and A, B, C (degrees, 3 decimals) of a frame into <paramref name="v"/> from index <paramref name="first"/>.</summary>
    private static void SetFrame(ref KukaValues v, Vector position, Rotation rotation, int first = 0)
    {
        (double a, double b, double c) = KrlFormat.Abc(rotation);
        v[first] = Math.Round(position.X, 3);
        v[first + 1] = Math.Round(position.Y, 3);
        v[first + 2] = Math.Round(position.Z, 3);
        v[first + 3] = Math.Round(KrlFormat.Degrees(a), 3);
        v[first + 4] = Math.Round(KrlFormat.Degrees(b), 3);
        v[first + 5] = Math.Round(KrlFormat.Degrees(c), 3);
    }

    private static T Known<T>(T? value, RobotAction action) where T : struct =>
        value ?? throw new InvalidOperationException($"The robot state after \"{action}\" has no value to send.");
}

namespace Machina;

/// <summary>
/// Turns an issued action into the integers the UR driver reads (spec online §7.4), from the cursor state after the action.
/// Only the last instruction of an action carries its id; helpers carry id 0, so each action is acknowledged once.
/// </summary>
internal static class UrActionEncoder
{
    /// <summary>Most integers one action produces (a pop of three settings: 3 × 3).</summary>
    public const int MaxValues = 16;

    /// <summary>Writes the instructions for <paramref name="action"/> into <paramref name="into"/> and returns how many integers (0 = nothing to send).</summary>
    public static int Encode(RobotAction action, RobotCursor after, Span<int> into)
    {
        int id = action.Id;
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                return Pose(into, id, after.MotionType == MotionType.Linear ? UrInstructionCode.MoveL : UrInstructionCode.MoveJPose,
                    Known(after.Position, action), Known(after.Rotation, action));
            case ActionAxes:
                Joints j = Known(after.Axes, action);
                return Put(into, id, UrInstructionCode.MoveJJoints,
                    UrWire.Degrees(j.J1), UrWire.Degrees(j.J2), UrWire.Degrees(j.J3), UrWire.Degrees(j.J4), UrWire.Degrees(j.J5), UrWire.Degrees(j.J6));
            case ActionWait wait:
                return Put(into, id, UrInstructionCode.Sleep, UrWire.Scale(wait.Millis));
            case ActionSpeed:
                return Put(into, id, UrInstructionCode.AllSpeed, UrWire.Millimetres(after.Speed));
            case ActionAcceleration:
                return Put(into, id, UrInstructionCode.AllAcceleration, UrWire.Millimetres(after.Acceleration));
            case ActionPrecision:
                return Put(into, id, UrInstructionCode.Blend, UrWire.Millimetres(after.Precision));
            case ActionAttachTool:
                Tool tool = after.Tool ?? throw new InvalidOperationException($"No tool is attached after \"{action}\".");
                return Tool(into, id, tool.TcpPosition, tool.TcpOrientation, tool.Weight);
            case ActionDetachTool:
                return Tool(into, id, Vector.Zero, Rotation.Identity, 0);
            case ActionIODigital digital:
                return Put(into, id, UrInstructionCode.SetDigitalOut, digital.PinNumber, digital.On ? 1 : 0, digital.IsToolPin ? 1 : 0);
            case ActionIOAnalog analog:
                return Put(into, id, UrInstructionCode.SetAnalogOut, analog.PinNumber, UrWire.Scale(analog.Value * UrWire.FactorAnalog));
            case ActionPushPop { Push: false }:
                return Pop(into, id, after);
            default:
                // Message, Comment, DefineTool, MotionMode, Push, Initialization: nothing the robot does (UrOnline refuses the rest).
                return 0;
        }
    }

    private static int Pose(Span<int> into, int id, UrInstructionCode code, Vector p, Rotation r)
    {
        RotationVector rv = r.ToRotationVector();
        return Put(into, id, code, UrWire.Millimetres(p.X), UrWire.Millimetres(p.Y), UrWire.Millimetres(p.Z), UrWire.Degrees(rv.X), UrWire.Degrees(rv.Y), UrWire.Degrees(rv.Z));
    }

    private static int Tool(Span<int> into, int id, Vector p, Rotation r, double kg)
    {
        int n = Pose(into, id, UrInstructionCode.SetTool, p, r);
        into[n] = UrWire.Scale(kg * UrWire.FactorKilogram);
        return n + 1;
    }

    /// <summary>One instruction per setting the pop changed; only the last carries the id. Nothing when nothing changed.</summary>
    private static int Pop(Span<int> into, int id, RobotCursor after)
    {
        var before = after.SettingsBeforeLastPop ?? after.CurrentSettings;
        int n = 0;
        if (before.Speed != after.Speed)
        {
            n += Put(into[n..], 0, UrInstructionCode.AllSpeed, UrWire.Millimetres(after.Speed));
        }
        if (before.Acceleration != after.Acceleration)
        {
            n += Put(into[n..], 0, UrInstructionCode.AllAcceleration, UrWire.Millimetres(after.Acceleration));
        }
        if (before.Precision != after.Precision)
        {
            n += Put(into[n..], 0, UrInstructionCode.Blend, UrWire.Millimetres(after.Precision));
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
}

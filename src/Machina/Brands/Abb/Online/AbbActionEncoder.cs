namespace Machina;

/// <summary>
/// Turns an issued action into the requests the ABB driver needs (spec online §6.6), reading every value from the
/// cursor state after the action. Only the last request of an action carries its id; helpers carry id 0 so each
/// action is acknowledged exactly once (fix of bugs A3 and A6).
/// </summary>
internal static class AbbActionEncoder
{
    /// <summary>Appends the requests for <paramref name="action"/> to <paramref name="into"/> and returns how many were added (0 = nothing to stream).</summary>
    public static int Encode(RobotAction action, RobotCursor after, ICollection<AbbRequest> into)
    {
        ArgumentNullException.ThrowIfNull(into);
        var block = new AbbRequestBlock();
        int count = Encode(action, after, ref block);
        for (int i = 0; i < count; i++)
        {
            into.Add(block[i]);
        }
        return count;
    }

    /// <summary>As the other overload, into a block on the caller's stack (the stream encodes every action: no list, no array).</summary>
    public static int Encode(RobotAction action, RobotCursor after, ref AbbRequestBlock into)
    {
        ArgumentNullException.ThrowIfNull(action);
        ArgumentNullException.ThrowIfNull(after);
        int before = into.Count;
        int id = action.Id;
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                into.Add(AbbRequest.Move(id, after.MotionType == MotionType.Linear, Known(after.Position, action), Known(after.Rotation, action)));
                break;
            case ActionArcMotion:
                into.Add(AbbRequest.ArcThroughOrientation(Known(after.ArcThroughRotation, action)));
                into.Add(AbbRequest.MoveC(id, Known(after.Position, action), Known(after.Rotation, action), Known(after.ArcThrough, action)));
                break;
            case ActionAxes:
                into.Add(AbbRequest.MoveAbsJ(id, Known(after.Axes, action)));
                break;
            case ActionSpeed:
                into.Add(AbbRequest.Speed(id, after.Speed));
                break;
            case ActionAcceleration:
                into.Add(AbbRequest.Acceleration(id, after.Acceleration));
                break;
            case ActionPrecision:
                into.Add(AbbRequest.Zone(id, after.Precision));
                break;
            case ActionWait wait:
                into.Add(AbbRequest.WaitTime(id, wait.Millis));
                break;
            case ActionMessage message:
                into.Add(AbbRequest.TPWrite(id, message.Message));
                break;
            case ActionAttachTool:
                var tool = after.Tool ?? throw new InvalidOperationException($"No tool is attached after \"{action}\".");
                into.Add(AbbRequest.Tool(id, tool.TcpPosition, tool.TcpOrientation, tool.Weight, tool.CenterOfGravity));
                break;
            case ActionDetachTool:
                into.Add(AbbRequest.NoTool(id));
                break;
            case ActionIODigital digital:
                into.Add(AbbRequest.SetDO(id, digital.PinName, digital.On));
                break;
            case ActionIOAnalog analog:
                into.Add(AbbRequest.SetAO(id, analog.PinName, analog.Value));
                break;
            case ActionReadInput read:
                into.Add(AbbRequest.ReadInput(id, read.PinName, read.IsAnalog));
                break;
            case ActionWaitDigital wait:
                into.Add(AbbRequest.WaitDI(id, wait.PinName, wait.On, wait.TimeoutMillis));
                break;
            case ActionPushPop { Push: false }:
                EncodePop(id, after, ref into);
                break;
            case ActionExternalAxis axis:
                EncodeExternalAxis(id, axis.Target, after, ref into);
                break;
            case ActionArmAngle arm:
                into.Add(AbbRequest.ExternalAxesRobTarget(id, new ExternalAxes(after.ArmAngle ?? arm.Angle)));
                break;
            case ActionCustomCode { IsDeclaration: false } custom:
                into.Add(AbbRequest.Custom(id, custom.Statement));
                break;
            case ActionPushPop or ActionDefineTool or ActionMotionMode or ActionCoordinates or ActionComment or ActionCustomCode
                or ActionInitialization or ActionTemperature or ActionExtrusion or ActionExtrusionRate:
                // Kept on the host side (Push, DefineTool, MotionMode, Coordinates: they change the next requests), comments and
                // declarations, and 3D-printing actions with no meaning on an ABB arm: nothing to stream.
                break;
            default:
                throw ActionKinds.Unhandled(action, "The ABB encoder");
        }
        return into.Count - before;
    }

    /// <summary>One request per setting the pop changed; only the last carries the id. Nothing when nothing changed.</summary>
    private static void EncodePop(int id, RobotCursor after, ref AbbRequestBlock into)
    {
        var old = after.SettingsBeforeLastPop ?? after.CurrentSettings;
        var changes = new List<Func<int, AbbRequest>>(3);
        if (old.Speed != after.Speed)
        {
            changes.Add(i => AbbRequest.Speed(i, after.Speed));
        }
        if (old.Acceleration != after.Acceleration)
        {
            changes.Add(i => AbbRequest.Acceleration(i, after.Acceleration));
        }
        if (old.Precision != after.Precision)
        {
            changes.Add(i => AbbRequest.Zone(i, after.Precision));
        }
        for (int i = 0; i < changes.Count; i++)
        {
            into.Add(changes[i](i == changes.Count - 1 ? id : 0));
        }
    }

    private static void EncodeExternalAxis(int id, ExternalAxesTarget target, RobotCursor after, ref AbbRequestBlock into)
    {
        var cartesian = after.ExternalAxesCartesian ?? ExternalAxes.None;
        var joints = after.ExternalAxesJoints ?? ExternalAxes.None;
        switch (target)
        {
            case ExternalAxesTarget.Cartesian:
                into.Add(AbbRequest.ExternalAxesRobTarget(id, cartesian));
                break;
            case ExternalAxesTarget.Joint:
                into.Add(AbbRequest.ExternalAxesJointTarget(id, joints));
                break;
            default:
                into.Add(AbbRequest.ExternalAxesRobTarget(0, cartesian));
                into.Add(AbbRequest.ExternalAxesJointTarget(id, joints));
                break;
        }
    }

    private static T Known<T>(T? value, RobotAction action) where T : struct =>
        value ?? throw new InvalidOperationException($"The robot state after \"{action}\" has no value to send.");
}

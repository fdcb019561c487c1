namespace Machina;

/// <summary>
/// Turns one released action into the requests for the RAPID driver (spec online §6.6), reading absolute targets from the
/// release cursor's state after the action. Fixes of the original: acceleration in m/s², one analog write, one
/// acknowledged request per action (earlier requests of pop and external-axes "All" carry id 0).
/// </summary>
internal static class AbbActionTranslator
{
    /// <summary>Most requests one action produces.</summary>
    internal const int MaxRequests = 3;

    /// <summary>Writes the requests of <paramref name="action"/> into <paramref name="requests"/> and returns how many; 0 = nothing to send.</summary>
    internal static int Translate(RobotAction action, RobotCursor state, int id, Span<AbbRequest> requests)
    {
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation:
                requests[0] = AbbRequest.Move(id, state.MotionType == MotionType.Linear, Require(state.Position, action), Require(state.Rotation, action));
                return 1;
            case ActionArcMotion:
                requests[0] = AbbRequest.MoveC(id, Require(state.Position, action), Require(state.Rotation, action), Require(state.ArcThrough, action));
                return 1;
            case ActionAxes:
                requests[0] = AbbRequest.MoveAbsJ(id, Require(state.Axes, action));
                return 1;
            case ActionSpeed:
                requests[0] = AbbRequest.Speed(id, state.Speed);
                return 1;
            case ActionAcceleration:
                requests[0] = AbbRequest.Acceleration(id, state.Acceleration);
                return 1;
            case ActionPrecision:
                requests[0] = AbbRequest.Zone(id, state.Precision);
                return 1;
            case ActionWait w:
                requests[0] = AbbRequest.WaitTime(id, w.Millis);
                return 1;
            case ActionMessage m:
                requests[0] = AbbRequest.TPWrite(id, m.Message);
                return 1;
            case ActionAttachTool:
                Tool tool = state.Tool ?? throw new InvalidOperationException("no tool is attached after AttachTool");
                requests[0] = AbbRequest.Tool(id, tool.TcpPosition, tool.TcpOrientation, tool.Weight, tool.CenterOfGravity);
                return 1;
            case ActionDetachTool:
                requests[0] = AbbRequest.NoTool(id);
                return 1;
            case ActionIODigital d:
                requests[0] = AbbRequest.SetDO(id, d.PinName, d.On);
                return 1;
            case ActionIOAnalog a:
                requests[0] = AbbRequest.SetAO(id, a.PinName, a.Value);
                return 1;
            case ActionExternalAxis e:
                return ExternalAxes(e.Target, state, id, requests);
            case ActionArmAngle:
                requests[0] = AbbRequest.ExternalAxesRobTarget(id, new ExternalAxes(state.ArmAngle));
                return 1;
            case ActionCustomCode c when !c.IsDeclaration:
                requests[0] = AbbRequest.Custom(id, c.Statement);
                return 1;
            case ActionPushPop { Push: false }:
                return Pop(state, id, requests);
            default:
                return 0; // push, motion mode, coordinates, comments, tool definitions, 3D printing: nothing to send
        }
    }

    private static int ExternalAxes(ExternalAxesTarget target, RobotCursor state, int id, Span<AbbRequest> requests)
    {
        ExternalAxes cartesian = state.ExternalAxesCartesian ?? Machina.ExternalAxes.None;
        ExternalAxes joints = state.ExternalAxesJoints ?? Machina.ExternalAxes.None;
        switch (target)
        {
            case ExternalAxesTarget.Cartesian:
                requests[0] = AbbRequest.ExternalAxesRobTarget(id, cartesian);
                return 1;
            case ExternalAxesTarget.Joint:
                requests[0] = AbbRequest.ExternalAxesJointTarget(id, joints);
                return 1;
            default:
                requests[0] = AbbRequest.ExternalAxesRobTarget(0, cartesian);
                requests[1] = AbbRequest.ExternalAxesJointTarget(id, joints);
                return 2;
        }
    }

    private static int Pop(RobotCursor state, int id, Span<AbbRequest> requests)
    {
        if (state.SettingsBeforeLastPop is not Settings before)
        {
            return 0;
        }
        int n = 0;
        if (before.Speed != state.Speed)
        {
            requests[n++] = AbbRequest.Speed(0, state.Speed);
        }
        if (before.Acceleration != state.Acceleration)
        {
            requests[n++] = AbbRequest.Acceleration(0, state.Acceleration);
        }
        if (before.Precision != state.Precision)
        {
            requests[n++] = AbbRequest.Zone(0, state.Precision);
        }
        if (n > 0)
        {
            AbbRequest last = requests[n - 1];
            requests[n - 1] = last.Code switch
            {
                (int)AbbInstructionCode.Speed => AbbRequest.Speed(id, state.Speed),
                (int)AbbInstructionCode.Acceleration => AbbRequest.Acceleration(id, state.Acceleration),
                _ => AbbRequest.Zone(id, state.Precision),
            };
        }
        return n;
    }

    private static T Require<T>(T? value, RobotAction action) where T : struct =>
        value ?? throw new InvalidOperationException($"the target of {action.ToInstruction()} is not known");
}

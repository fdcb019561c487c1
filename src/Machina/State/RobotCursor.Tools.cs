namespace Machina;

internal sealed partial class RobotCursor
{
    private string? DefineTool(ActionDefineTool a)
    {
        if (Tools.ContainsKey(a.Tool.Name) && Warn is not null)
        {
            Warn(a, $"a tool named \"{a.Tool.Name}\" was already defined; the new definition replaces it.");
        }
        Tools[a.Tool.Name] = a.Tool;
        return null;
    }

    private string? AttachTool(ActionAttachTool a)
    {
        if (!Tools.TryGetValue(a.ToolName, out Tool? tool))
        {
            string known = Tools.Count == 0 ? "no tools are defined yet" : "defined tools: " + string.Join(", ", Tools.Keys);
            return $"no tool named \"{a.ToolName}\" is defined ({known}); use DefineTool first.";
        }
        if (Position is Vector pos && Rotation is Rotation rot)
        {
            (Vector flangePos, Rotation flangeRot) = Tool is null ? (pos, rot) : FlangeOf(pos, rot, Tool);
            Position = flangePos + flangeRot * tool.TcpPosition;
            Rotation = flangeRot * tool.TcpOrientation;
        }
        else
        {
            Notice?.Invoke(a, "the tool was attached while the tool pose is unknown; the pose will be known after the next absolute motion.");
        }
        Tool = tool;
        return null;
    }

    private string? DetachTool(ActionDetachTool a)
    {
        if (Tool is null)
        {
            return null;
        }
        if (Position is Vector pos && Rotation is Rotation rot)
        {
            (Vector flangePos, Rotation flangeRot) = FlangeOf(pos, rot, Tool);
            Position = flangePos;
            Rotation = flangeRot;
        }
        Tool = null;
        return null;
    }

    /// <summary>The flange pose that puts <paramref name="tool"/>'s tip at the given pose (exact inverse of attaching).</summary>
    internal static (Vector Position, Rotation Rotation) FlangeOf(Vector tcpPosition, Rotation tcpRotation, Tool tool)
    {
        Rotation flangeRot = tcpRotation * tool.TcpOrientation.Inverse();
        Vector flangePos = tcpPosition - flangeRot * tool.TcpPosition;
        return (flangePos, flangeRot);
    }
}

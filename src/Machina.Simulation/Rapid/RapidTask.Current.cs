namespace Machina.Simulation.Rapid;

/// <summary>The tool and work object of a motion task's last motion instruction (RAPID CTool, CWObj).</summary>
internal sealed partial class RapidTask
{
    /// <summary>The tooldata of the last motion (a copy), or null before the first one (then tool0).</summary>
    public RapidRecord? ToolData { get; private set; }

    /// <summary>The wobjdata of the last motion (a copy), or null for wobj0.</summary>
    public RapidRecord? WObjData { get; private set; }

    /// <summary>The tool frame of <see cref="ToolData"/> while <see cref="KeepsFrames"/> may be asked (MoveL, MoveJ and MoveC set it).</summary>
    public Pose ToolPose { get; private set; }

    /// <summary>The frame of <see cref="WObjData"/> (user frame then object frame) while <see cref="KeepsFrames"/> may be asked.</summary>
    public Pose WObjPose { get; private set; }

    private bool _posed;

    /// <summary>
    /// True when <paramref name="tool"/> and <paramref name="wobj"/> are identical to the data of the last MoveL, MoveJ or MoveC: their
    /// frames are <see cref="ToolPose"/> and <see cref="WObjPose"/> (a driver's every move: no tooldata or wobjdata read again).
    /// </summary>
    public bool KeepsFrames(RapidRecord tool, RapidRecord? wobj) =>
        _posed && ToolData is not null && RapidValues.Identical(tool, ToolData)
        && (wobj is null ? WObjData is null : WObjData is not null && RapidValues.Identical(wobj, WObjData));

    /// <summary>A MoveL, MoveJ or MoveC ran with data whose frames are <paramref name="toolPose"/> and <paramref name="wobjPose"/>.</summary>
    public void UsedFrames(RapidRecord tool, RapidRecord? wobj, Pose toolPose, Pose wobjPose)
    {
        UsedFrames(tool, wobj);
        ToolPose = toolPose;
        WObjPose = wobjPose;
        _posed = true;
    }

    /// <summary>A motion instruction ran with <paramref name="tool"/> and <paramref name="wobj"/> (null: none given, wobj0).</summary>
    public void UsedFrames(RapidRecord tool, RapidRecord? wobj)
    {
        _posed = false;
        // The copies are kept while the program moves with the same data (a driver's every MoveL): about 1.5 KB less per motion.
        if (ToolData is null || !RapidValues.Identical(tool, ToolData))
        {
            ToolData = (RapidRecord)RapidValues.Copy(tool);
        }
        if (wobj is null)
        {
            WObjData = null;
        }
        else if (WObjData is null || !RapidValues.Identical(wobj, WObjData))
        {
            WObjData = (RapidRecord)RapidValues.Copy(wobj);
        }
    }
}

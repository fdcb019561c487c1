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

    /// <summary>Where the tooldata and wobjdata of the last MoveL, MoveJ or MoveC were read, while they are known identical to the kept copies.</summary>
    private RapidCellMark _toolRead, _wobjRead;

    /// <summary>
    /// True when <paramref name="tool"/> and <paramref name="wobj"/> are identical to the data of the last MoveL, MoveJ or MoveC: their
    /// frames are <see cref="ToolPose"/> and <see cref="WObjPose"/> (a driver's every move: no tooldata or wobjdata read again). Data
    /// read from the same data as then, not written since (<paramref name="toolRead"/>, <paramref name="wobjRead"/>), are those data
    /// without a comparison of their ~40 components; otherwise they are compared, and where they were read is kept when identical.
    /// </summary>
    public bool KeepsFrames(RapidRecord tool, in RapidCellMark toolRead, RapidRecord? wobj, in RapidCellMark wobjRead)
    {
        if (!_posed || ToolData is null || (wobj is null) != (WObjData is null))
        {
            return false;
        }
        if (_toolRead.Same(toolRead) && (wobj is null || _wobjRead.Same(wobjRead)))
        {
            return true;
        }
        if (!RapidValues.Identical(tool, ToolData) || (wobj is not null && !RapidValues.Identical(wobj, WObjData!)))
        {
            return false;
        }
        _toolRead = toolRead;
        _wobjRead = wobjRead;
        return true;
    }

    /// <summary>A MoveL, MoveJ or MoveC ran with data (read where <paramref name="toolRead"/> and <paramref name="wobjRead"/> tell) whose frames are <paramref name="toolPose"/> and <paramref name="wobjPose"/>.</summary>
    public void UsedFrames(RapidRecord tool, in RapidCellMark toolRead, RapidRecord? wobj, in RapidCellMark wobjRead, Pose toolPose, Pose wobjPose)
    {
        UsedFrames(tool, wobj);
        ToolPose = toolPose;
        WObjPose = wobjPose;
        _posed = true;
        _toolRead = toolRead;
        _wobjRead = wobjRead;
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

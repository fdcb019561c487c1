namespace Machina.Simulation.Rapid;

/// <summary>The tool and work object of a motion task's last motion instruction (RAPID CTool, CWObj).</summary>
internal sealed partial class RapidTask
{
    /// <summary>The tooldata of the last motion (a copy), or null before the first one (then tool0).</summary>
    public RapidRecord? ToolData { get; private set; }

    /// <summary>The wobjdata of the last motion (a copy), or null for wobj0.</summary>
    public RapidRecord? WObjData { get; private set; }

    /// <summary>A motion instruction ran with <paramref name="tool"/> and <paramref name="wobj"/> (null: none given, wobj0).</summary>
    public void UsedFrames(RapidRecord tool, RapidRecord? wobj)
    {
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

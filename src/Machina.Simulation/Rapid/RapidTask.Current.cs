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
        ToolData = (RapidRecord)RapidValues.Copy(tool);
        WObjData = wobj is null ? null : (RapidRecord)RapidValues.Copy(wobj);
    }
}

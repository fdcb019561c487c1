namespace Machina;

public sealed partial class Robot
{
    private IActionStream? _online = null;
    private ControlType _controlType = ControlType.Offline;

    /// <summary>How this robot receives its actions: offline (compiled into a program, the default) or online (streamed).</summary>
    public ControlType GetControlMode() => _controlType;

    /// <summary>Chooses offline (actions are compiled) or online (actions are streamed to a controller).</summary>
    /// <returns>True when the mode is set.</returns>
    public bool ControlMode(ControlType mode)
    {
        mode = EnumText.RequireDefined(mode, nameof(mode));
        if (mode != ControlType.Offline)
        {
            throw new NotSupportedException("Online control is not available in this build yet.");
        }
        _controlType = mode;
        return true;
    }

    /// <summary>Chooses "offline" or "online" (any letter case).</summary>
    public bool ControlMode(string mode) => ControlMode(EnumText.Parse<ControlType>(mode, "control mode"));
}

namespace Machina;

/// <summary>How a robot receives its actions.</summary>
public enum ControlType
{
    /// <summary>Actions are collected and compiled into a program file (default).</summary>
    Offline,
    /// <summary>Actions are streamed to a driver running on the controller, as they are issued.</summary>
    Online,
    /// <summary>Old name of <see cref="Online"/>, kept so existing scripts work.</summary>
    Stream,
}

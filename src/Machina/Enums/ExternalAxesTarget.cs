namespace Machina;

/// <summary>Which kind of targets an external-axis value applies to.</summary>
public enum ExternalAxesTarget
{
    /// <summary>Both Cartesian and joint targets (default).</summary>
    All,
    /// <summary>Only Cartesian (MoveTo-like) targets.</summary>
    Cartesian,
    /// <summary>Only joint (AxesTo-like) targets.</summary>
    Joint,
}

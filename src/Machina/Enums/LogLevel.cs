namespace Machina;

/// <summary>How much a robot's log reports; each level includes the ones before it.</summary>
public enum LogLevel
{
    /// <summary>Nothing.</summary>
    NONE = 0,
    /// <summary>Only errors.</summary>
    ERROR = 1,
    /// <summary>Errors and warnings.</summary>
    WARNING = 2,
    /// <summary>Also general information (default).</summary>
    INFO = 3,
    /// <summary>Also the state after each relative action.</summary>
    VERBOSE = 4,
    /// <summary>Everything, for finding problems.</summary>
    DEBUG = 5,
}

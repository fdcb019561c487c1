namespace Machina.Simulation.Rapid;

/// <summary>
/// The predefined error numbers (<c>ERR_…</c>, data type errnum) that the twin raises or that programs test in error handlers.
/// The names and meanings are RAPID's; the numeric values are the twin's own (programs compare them by name).
/// </summary>
internal static partial class RapidErrorNumbers
{
    /// <summary>A motion target out of reach or beyond a joint limit.</summary>
    public const int RobLimit = 41001;

    /// <summary>Division by zero.</summary>
    public const int DivZero = 41002;

    /// <summary>An array index out of its bounds.</summary>
    public const int OutOfBounds = 41003;

    /// <summary>A socket call timed out.</summary>
    public const int SockTimeout = 41004;

    /// <summary>The socket was closed (by the other end, or not connected).</summary>
    public const int SockClosed = 41005;

    /// <summary>A WaitDI timed out.</summary>
    public const int WaitMaxTime = 41006;

    /// <summary>An unknown signal name given to AliasIO.</summary>
    public const int AliasIoDef = 41007;

    /// <summary>A signal variable used before AliasIO gave it a signal.</summary>
    public const int NoAliasIoDef = 41008;

    /// <summary>A value out of its allowed range (e.g. a negative WaitTime, an analog value beyond its limits).</summary>
    public const int ArgValErr = 41009;

    /// <summary>A string longer than 80 characters.</summary>
    public const int StringTooLong = 41010;

    /// <summary>An arithmetic overflow.</summary>
    public const int NumOverflow = 41011;

    /// <summary>A socket that is already created or bound.</summary>
    public const int SockAddrInUse = 41012;

    /// <summary>An optional parameter used without being present.</summary>
    public const int NotPres = 41013;

    /// <summary>The error numbers by name, as the binder offers them.</summary>
    public static IReadOnlyDictionary<string, int> ByName { get; } = WithCatalog(new Dictionary<string, int>(StringComparer.OrdinalIgnoreCase)
    {
        ["ERR_ROBLIMIT"] = RobLimit, ["ERR_DIVZERO"] = DivZero, ["ERR_OUTOFBND"] = OutOfBounds, ["ERR_SOCK_TIMEOUT"] = SockTimeout,
        ["ERR_SOCK_CLOSED"] = SockClosed, ["ERR_WAIT_MAXTIME"] = WaitMaxTime, ["ERR_ALIASIO_DEF"] = AliasIoDef,
        ["ERR_NO_ALIASIO_DEF"] = NoAliasIoDef, ["ERR_ARGVALERR"] = ArgValErr, ["ERR_STRTOOLNG"] = StringTooLong,
        ["ERR_NUMOVERFLOW"] = NumOverflow, ["ERR_SOCK_ADDR_INUSE"] = SockAddrInUse, ["ERR_NOTPRES"] = NotPres,
    });
}

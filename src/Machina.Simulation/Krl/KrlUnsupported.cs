namespace Machina.Simulation.Krl;

/// <summary>
/// Names of controller options and system routines the twin does not have, with why: a program that uses them is refused at load
/// with that reason rather than with "unknown routine" (docs/simulation.md, the KUKA table).
/// </summary>
internal static class KrlUnsupported
{
    private const string Channels = "it reads the controller's command channel or reads and writes its serial channels and byte buffers, which the twin does not model";

    /// <summary>
    /// RSI's routines and types are declared by the option's own files: a controller without it refuses the program when it is
    /// selected, its names not declared (KSS: "Name not declared as subprogram", as a third-party note quotes the linking error of
    /// a missing option package). The twin refuses it at load, the same point, with the option named.
    /// </summary>
    private const string Rsi = "the Robot Sensor Interface (RSI, a KUKA option) is not installed on the twin, so it is refused at load as a controller without the option refuses it at program selection; EthernetKRL is installed";

    private const string Eki6 = "it is EthernetKRL for iiQKA.OS2 (EKI_Load, EKI_ReadNext, EKI_Unload, INT results); the twin has EthernetKRL for the KUKA System Software (EKI_Init, EKI_Open, EKI_CheckBuffer, EKI_STATUS results)";

    /// <summary>Why routine <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Routine(string name)
    {
        string upper = name.ToUpperInvariant();
        return upper switch
        {
            "CREAD" or "SWRITE" or "SREAD" or "CAST_TO" or "CAST_FROM" => $"{upper} is not supported by the twin: {Channels}",
            _ when upper.StartsWith("RSI_", StringComparison.Ordinal) => $"{upper}: name not declared as subprogram: {Rsi}",
            "EKI_LOAD" or "EKI_UNLOAD" or "EKI_READNEXT" => $"{upper} is not supported by the twin: {Eki6}",
            _ => null,
        };
    }

    /// <summary>Why data type <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Type(string name) => name.ToUpperInvariant() switch
    {
        "RSIERR" or "RSI_STATE" or "RSI_MOVECORR" => $"{name.ToUpperInvariant()}: name not declared as data type: {Rsi}",
        "PRO_MODE" => "the data type PRO_MODE is not supported by the twin: the program run modes ($PRO_MODE: #GO, #MSTEP, #ISTEP…) are not modelled",
        _ => null,
    };
}

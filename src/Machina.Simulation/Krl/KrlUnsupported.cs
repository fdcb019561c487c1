namespace Machina.Simulation.Krl;

/// <summary>
/// Names of controller options and system routines the twin does not have, with why: a program that uses them is refused at load
/// with that reason rather than with "unknown routine" (docs/simulation.md, the KUKA table).
/// </summary>
internal static class KrlUnsupported
{
    private const string Channels = "it reads the controller's command channel or reads and writes its serial channels and byte buffers, which the twin does not model";

    /// <summary>
    /// The twin has the RSI routines the published RSI clients call (KrlTwinController.Rsi.cs, .RsiKrc2.cs); other RSI routines are
    /// refused at load with what the twin has.
    /// </summary>
    private const string Rsi = "the twin has RSI_CREATE, RSI_ON, RSI_MOVECORR, RSI_OFF, RSI_DELETE, RSI_SETPUBLICPAR and RSI_GETPUBLICPAR of RSI 3 and 4 (and RSI 2's ST_ETHERNET, ST_AXISCORR, ST_NEWLINK, ST_SETPARAM, ST_ON, ST_SKIPSENS, ST_OFF)";

    private const string Eki6 = "it is EthernetKRL for iiQKA.OS2 (EKI_Load, EKI_ReadNext, EKI_Unload, INT results); the twin has EthernetKRL for the KUKA System Software (EKI_Init, EKI_Open, EKI_CheckBuffer, EKI_STATUS results)";

    /// <summary>Why routine <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Routine(string name)
    {
        string upper = name.ToUpperInvariant();
        return upper switch
        {
            "CREAD" or "SWRITE" or "SREAD" or "CAST_TO" or "CAST_FROM" => $"{upper} is not supported by the twin: {Channels}",
            "RSI_LOAD" or "RSI_ACTIVATE" or "RSI_PROCESS_ON" or "RSI_PROCESS_OFF" => $"{upper} is not supported by the twin: it is RSI for iiQKA.OS2; {Rsi}",
            _ when upper.StartsWith("RSI_", StringComparison.Ordinal) || upper.StartsWith("ST_", StringComparison.Ordinal) => $"{upper} is not supported by the twin: {Rsi}",
            "EKI_LOAD" or "EKI_UNLOAD" or "EKI_READNEXT" => $"{upper} is not supported by the twin: {Eki6}",
            _ => null,
        };
    }

    /// <summary>Why data type <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Type(string name) => name.ToUpperInvariant() switch
    {
        "RSI_STATE" => $"the data type RSI_STATE is not supported by the twin: {Rsi}",
        "PRO_MODE" => "the data type PRO_MODE is not supported by the twin: the program run modes ($PRO_MODE: #GO, #MSTEP, #ISTEP…) are not modelled",
        _ => null,
    };
}

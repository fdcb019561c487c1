namespace Machina.Simulation.Krl;

/// <summary>
/// Names of controller options and system routines the twin does not have, with why: a program that uses them is refused at load
/// with that reason rather than with "unknown routine" (docs/simulation.md, the KUKA table).
/// </summary>
internal static class KrlUnsupported
{
    private const string Channels = "it reads or writes the controller's command and serial channels ($CMD: program management; $CMD is not modelled)";

    private const string Rsi = "the Robot Sensor Interface (RSI, a KUKA option) is not on the twin; EthernetKRL is";

    /// <summary>Why routine <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Routine(string name)
    {
        string upper = name.ToUpperInvariant();
        return upper switch
        {
            "CWRITE" or "CREAD" or "SWRITE" or "SREAD" or "CAST_TO" or "CAST_FROM" => $"{upper} is not supported by the twin: {Channels}",
            _ when upper.StartsWith("RSI_", StringComparison.Ordinal) => $"{upper} is not supported by the twin: {Rsi}",
            _ => null,
        };
    }

    /// <summary>Why data type <paramref name="name"/> is not on the twin, or null when it is simply unknown.</summary>
    public static string? Type(string name) => name.ToUpperInvariant() switch
    {
        "RSIERR" or "RSI_STATE" or "RSI_MOVECORR" => $"the data type {name.ToUpperInvariant()} is not supported by the twin: {Rsi}",
        "PRO_STATE" or "PRO_MODE" => $"the data type {name.ToUpperInvariant()} is not supported by the twin: program management ($PRO_STATE, $PRO_MODE, CWRITE($CMD)) is not modelled",
        _ => null,
    };
}

namespace Machina.Simulation.Krl;

/// <summary>
/// EKI_CHECK(status, message type [, channel]) of the EthernetKRL manual ("Checking functions for errors"): reads the error
/// number of an EKI function's EKI_STATUS and shows its message on the smartHMI. The twin shows it on the pendant; a #QUIT
/// (acknowledgement) message stops the program there, as no operator can acknowledge it (approximated: the manual pages found
/// do not say how the controller holds a program on it). Msg_No 0 shows nothing.
/// </summary>
internal sealed partial class KrlTwinController
{
    private void AddEkiCheck() =>
        Environment.Builtins["EKI_CHECK"] = new KrlBuiltin("EKI_CHECK", null,
            [new(KrlTypes.EkiStatus), new(KrlType.Enum), new(KrlType.Array(KrlType.Char, 0), Optional: true)], (_, a) =>
            {
                int number = KrlValues.ToInt(((KrlStructValue)a[0]).Values[2]);
                if (number == 0)
                {
                    return null;
                }
                string type = a[1] is KrlEnumValue e ? e.Name.ToUpperInvariant() : "NOTIFY";
                string channel = a.Length > 2 && a[2] is { } named ? $" ({Str(named)})" : "";
                string text = $"EthernetKRL{channel}: EKI{number:00000}: {EkiMessage(number)}";
                if (type == "QUIT")
                {
                    throw new KrlRuntimeException($"{text} (EKI_CHECK with #QUIT: an acknowledgement message, which stops the program on the twin)");
                }
                Pendant.Log(text);
                return null;
            });

    /// <summary>The texts of the EthernetKRL errors the twin returns (the numbers and texts as users quote them).</summary>
    private static string EkiMessage(int number) => number switch
    {
        EkiNoConnection => "Connection not available",
        EkiAlreadyInitialised => "Initialization already performed",
        _ => "error",
    };
}

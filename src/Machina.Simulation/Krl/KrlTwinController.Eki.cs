namespace Machina.Simulation.Krl;

/// <summary>EthernetKRL channels of the controller.</summary>
internal sealed partial class KrlTwinController
{
    /// <summary>How many EthernetKRL channels are open.</summary>
    public int EkiOpenChannels => 0;

    private void AddEki()
    {
    }

    private void CloseEki()
    {
        _inputsChanged.Dispose();
    }
}

using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

internal sealed partial class KrlTwinController
{
    /// <summary>
    /// What the robot interpreter's EKI_Send of the driver channel hands to the EthernetKRL stack, held until the interpreter is
    /// about to wait (<see cref="TwinHeldOutbox"/>; a controller around the twin attaches the connection to it).
    /// </summary>
    public TwinHeldSends Sends { get; } = new();
}

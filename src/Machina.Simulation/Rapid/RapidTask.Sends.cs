using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

internal sealed partial class RapidTask
{
    /// <summary>The task's socket sends held by the controller's network stack until the task waits (<see cref="TwinHeldOutbox"/>).</summary>
    public TwinHeldSends Sends { get; } = new();
}

using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>
    /// The fault plan's RestartLosingProgress, as a power cycle: the output integer registers Machina's driver keeps its progress
    /// in (24: last executed, 25: last received) are 0 again, as a controller that starts up has them. The program that ran the
    /// last request found its connection closed and halts at its next read (it writes no register without an instruction); the
    /// next program the host sends reports no progress. Register 26 (the instance) is left to that program, which writes it
    /// as it starts, possibly before this runs.
    /// </summary>
    private protected override void RestartingLosingProgress()
    {
        foreach (int register in (ReadOnlySpan<int>)[24, 25])
        {
            Twin.Io.SetNumber(UrIoBanks.OutputIntRegisters, register, 0);
        }
    }
}

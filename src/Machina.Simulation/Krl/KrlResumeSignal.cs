namespace Machina.Simulation.Krl;

/// <summary>
/// RESUME in an interrupt routine: the interrupt routine and every subprogram the interrupt broke into end (a motion under way is
/// abandoned where the arm stands), and the program goes on after the call, in the routine that declared the interrupt, that led there.
/// </summary>
internal sealed class KrlResumeSignal(object[] declaringFrame, int line, string file) : Exception($"RESUME at {file}, line {line}")
{
    /// <summary>The frame of the routine run that declared the interrupt: its call statement that was running is where the program goes on.</summary>
    public object[] DeclaringFrame { get; } = declaringFrame;

    /// <summary>The line of the RESUME.</summary>
    public int Line { get; } = line;

    /// <summary>The file of the RESUME.</summary>
    public string File { get; } = file;
}

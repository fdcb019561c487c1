namespace Machina.Simulation.Krl;

/// <summary>
/// A declared interrupt of one interpreter: its declaration, the frame it was declared in, whether it is switched on and its
/// condition's value at the last look. One object per priority, changed in place when the priority is declared again, so that the
/// interpreter's look at its conditions (several times an action) walks an array in priority order instead of looking each up.
/// </summary>
internal sealed class KrlInterruptState(KrlInterruptDecl declaration, object[] frame)
{
    /// <summary>The declaration (<c>INTERRUPT DECL</c>) in force for the priority.</summary>
    public KrlInterruptDecl Declaration { get; set; } = declaration;

    /// <summary>The frame of the routine that declared it (its condition and handler's arguments are evaluated there).</summary>
    public object[] Frame { get; set; } = frame;

    /// <summary>True while switched on (<c>INTERRUPT ON</c>).</summary>
    public bool On { get; set; }

    /// <summary>The condition's value at the last look (an interrupt fires on the rising edge).</summary>
    public bool Last { get; set; }
}

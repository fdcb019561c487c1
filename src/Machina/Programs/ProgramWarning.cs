namespace Machina;

/// <summary>Something in a program the device cannot do exactly as asked (e.g. a rotation on a 3D printer), with the action concerned.</summary>
/// <param name="ActionId">Id of the action, or −1.</param>
/// <param name="Instruction">The action's instruction text, or empty.</param>
/// <param name="Message">What happened, in plain words.</param>
public sealed record ProgramWarning(int ActionId, string Instruction, string Message)
{
    /// <summary>For a warning from a kinematic pre-flight check (robot model set): which check; otherwise null.</summary>
    public KinematicIssueKind? Kind { get; init; }

    /// <summary>When the program was compiled from instruction text: the line (from 1) of the action's statement; otherwise null.</summary>
    public int? Line { get; init; }

    /// <summary>When the program was compiled from instruction text: the column (from 1) where the action's statement starts; otherwise null.</summary>
    public int? Column { get; init; }

    /// <summary>Text such as <c>#4 Rotate(0,1,0,-90); rotations are not applicable to a 3D printer</c>.</summary>
    public override string ToString() => ActionId >= 0 ? $"#{ActionId} {Instruction} {Message}" : Message;
}

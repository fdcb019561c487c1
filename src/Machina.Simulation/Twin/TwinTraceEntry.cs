namespace Machina.Simulation.Twin;

/// <summary>What a traced step of a program did.</summary>
internal enum TwinTraceKind
{
    /// <summary>A motion ended (the arm got there).</summary>
    Motion,

    /// <summary>An output was set.</summary>
    Output,

    /// <summary>The tool (TCP) or payload changed.</summary>
    Tool,

    /// <summary>A wait.</summary>
    Wait,

    /// <summary>A message for the operator.</summary>
    Message,
}

/// <summary>One step of a program as the twin controller did it: where the arm is after it, at which program line (a value: the trace holds it in place, one per streamed action).</summary>
/// <param name="Line">The program line.</param>
/// <param name="Kind">What the step did.</param>
/// <param name="Joints">The joints after the step (degrees).</param>
/// <param name="Tcp">The tool centre point after the step (mm, base frame).</param>
/// <param name="Text">A short description, e.g. <c>movel</c> or <c>standard_digital_out[1] = True</c>.</param>
/// <param name="Seconds">Program time at the end of the step.</param>
internal readonly record struct TwinTraceEntry(int Line, TwinTraceKind Kind, Joints Joints, Pose Tcp, string Text, double Seconds);

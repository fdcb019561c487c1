namespace Machina.Simulation.Krl;

/// <summary>
/// The line a trace entry of a written output or tool carries: the line of the interpreter that wrote it. The robot interpreter
/// and the submit interpreter run on their own threads; when both wrote one shared line, a streamed <c>$OUT</c> write of the
/// robot program was traced at the line the submit interpreter (the KUKA monitor) had just run, or not, as the threads met.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>The robot interpreter's line (<see cref="Line"/>), which its machine writes before each statement.</summary>
    private readonly KrlRunningLine _robotLine = new();

    /// <summary>The program line the robot interpreter runs now (traces of its outputs carry it).</summary>
    public int Line => _robotLine.Value;

    /// <summary>The line the robot interpreter's machine writes before each statement.</summary>
    internal KrlRunningLine RobotLine => _robotLine;

    /// <summary>
    /// The line of the interpreter on this thread: a submit interpreter's own when it runs here, else the robot interpreter's
    /// (the robot program's thread, and a host or the EKI reader writing for it).
    /// </summary>
    private int TraceLine() => SubmitLineHere()?.Value ?? Line;
}

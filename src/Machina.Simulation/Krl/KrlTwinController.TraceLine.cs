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

    /// <summary>The running submit interpreters' lines, each with the thread that runs it. Guarded by itself.</summary>
    private readonly List<(int Thread, KrlRunningLine Line)> _submitLines = [];

    /// <summary>The program line the robot interpreter runs now (traces of its outputs carry it).</summary>
    public int Line => _robotLine.Value;

    /// <summary>The line the robot interpreter's machine writes before each statement.</summary>
    internal KrlRunningLine RobotLine => _robotLine;

    /// <summary>
    /// The line of the interpreter on this thread: a submit interpreter's own when it runs here, else the robot interpreter's
    /// (the robot program's thread, and a host or the EKI reader writing for it). Submit interpreters are looked for only while one runs.
    /// </summary>
    private int TraceLine()
    {
        if (Volatile.Read(ref _submitsRunning) > 0)
        {
            int thread = System.Environment.CurrentManagedThreadId;
            lock (_submitLines)
            {
                foreach ((int submitThread, KrlRunningLine line) in _submitLines)
                {
                    if (submitThread == thread)
                    {
                        return line.Value;
                    }
                }
            }
        }
        return Line;
    }

    /// <summary>Keeps <paramref name="line"/> as the line of the submit interpreter on this thread until the result is disposed.</summary>
    private SubmitLine SubmitLineOnThisThread(KrlRunningLine line)
    {
        (int Thread, KrlRunningLine Line) entry = (System.Environment.CurrentManagedThreadId, line);
        lock (_submitLines)
        {
            _submitLines.Add(entry);
        }
        return new SubmitLine(this, entry);
    }

    /// <summary>A submit interpreter's line kept, for <see cref="TraceLine"/>.</summary>
    private readonly struct SubmitLine(KrlTwinController controller, (int Thread, KrlRunningLine Line) entry) : IDisposable
    {
        public void Dispose()
        {
            lock (controller._submitLines)
            {
                controller._submitLines.Remove(entry);
            }
        }
    }
}

namespace Machina.Simulation.Twin;

/// <summary>The log a controller shows on its teach pendant: messages of programs and errors, in order.</summary>
internal sealed class TwinPendant
{
    private readonly List<string> _lines = [];
    private readonly Lock _gate = new();

    /// <summary>Raised after a line is added (on the program's thread).</summary>
    public event Action<string>? Logged;

    /// <summary>A copy of the lines so far.</summary>
    public IReadOnlyList<string> Lines
    {
        get
        {
            lock (_gate)
            {
                return [.. _lines];
            }
        }
    }

    /// <summary>Adds a line, made printable (a program's text can carry bytes from the wire: escape codes are shown as <c>\x1b</c>).</summary>
    public void Log(string line)
    {
        line = PrintableText.Of(line);
        lock (_gate)
        {
            _lines.Add(line);
        }
        Logged?.Invoke(line);
    }
}

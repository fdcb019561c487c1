namespace Machina.Simulation.Krl;

/// <summary>An error that stops the robot interpreter, with the message the controller shows and where it happened.</summary>
internal sealed class KrlRuntimeException(string message) : Exception(message)
{
    /// <summary>The file the interpreter was in (set where it is caught first).</summary>
    public string? File { get; set; }

    /// <summary>The line (0 until known).</summary>
    public int Line { get; set; }
}

/// <summary>HALT, or a stop that ends the program for good: the interpreter stops where it is.</summary>
internal sealed class KrlHaltException(int line, string file) : Exception($"HALT at {file}, line {line}")
{
    /// <summary>The line of the HALT.</summary>
    public int Line { get; } = line;

    /// <summary>The file of the HALT.</summary>
    public string File { get; } = file;
}

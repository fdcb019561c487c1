namespace Machina.Simulation.UrScript;

/// <summary>A program the controller refuses before running it (syntax, unknown name or function, wrong arguments).</summary>
internal sealed class UrCompileException(int line, string message) : Exception($"Compile error: line {line}: {message}")
{
    /// <summary>The 1-based line of the program where the error is.</summary>
    public int Line { get; } = line;

    /// <summary>The reason alone, without the line.</summary>
    public string Reason { get; } = message;
}

/// <summary>An error while a program runs: the controller stops the program and shows this message.</summary>
internal sealed class UrRuntimeException(int line, string message) : Exception($"Runtime error: line {line}: {message}")
{
    /// <summary>The 1-based line of the program where the error is (0 when unknown).</summary>
    public int Line { get; } = line;

    /// <summary>The reason alone, without the line.</summary>
    public string Reason { get; } = message;
}

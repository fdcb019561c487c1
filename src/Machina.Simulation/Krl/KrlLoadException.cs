namespace Machina.Simulation.Krl;

/// <summary>A KRL file the controller refuses to load: a syntax error, an unknown name or a type error, at a line of a file.</summary>
internal sealed class KrlLoadException(string file, int line, string reason) : Exception($"{file}, line {line}: {reason}")
{
    /// <summary>The file (e.g. <c>machina_kuka_driver.src</c>).</summary>
    public string File { get; } = file;

    /// <summary>The 1-based line.</summary>
    public int Line { get; } = line;

    /// <summary>The reason alone.</summary>
    public string Reason { get; } = reason;
}

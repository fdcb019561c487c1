namespace Machina;

/// <summary>Instruction text that could not be read, with the line and column (both from 1) where the problem is.</summary>
public sealed class InstructionParseException : FormatException
{
    /// <summary>Creates the exception.</summary>
    public InstructionParseException(int line, int column, string problem)
        : base($"Line {line}, column {column}: {problem}")
    {
        Line = line;
        Column = column;
        Problem = problem;
    }

    /// <summary>Line of the problem, from 1.</summary>
    public int Line { get; }

    /// <summary>Column of the problem, from 1.</summary>
    public int Column { get; }

    /// <summary>What is wrong, without the position.</summary>
    public string Problem { get; }
}

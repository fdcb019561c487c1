namespace Machina;

/// <summary>
/// One statement of an instruction text: the action it makes, and the line and column (from 1) where it starts. The command
/// line reads programs this way, so that every message about an action can point at the statement that wrote it.
/// </summary>
/// <param name="Action">The action the statement makes (not issued yet: its id is -1).</param>
/// <param name="Line">Line of the statement's first character, from 1.</param>
/// <param name="Column">Column of the statement's first character, from 1.</param>
public readonly record struct InstructionStatement(RobotAction Action, int Line, int Column)
{
    /// <summary>
    /// The statements of <paramref name="reader"/>, read and parsed as they are enumerated (constant memory, whatever the length),
    /// with the library's own reader (the rules of <c>Robot.Do</c> and <c>Instructions.Parse</c>).
    /// </summary>
    /// <exception cref="InstructionParseException">A statement is malformed: its line, column and problem.</exception>
    public static IEnumerable<InstructionStatement> ReadAll(TextReader reader, CancellationToken cancellationToken = default)
    {
        var instructions = new InstructionReader(reader);
        while (true)
        {
            cancellationToken.ThrowIfCancellationRequested();
            if (instructions.Next() is not RobotAction action)
            {
                yield break;
            }
            yield return new InstructionStatement(action, instructions.Line, instructions.Column);
        }
    }
}

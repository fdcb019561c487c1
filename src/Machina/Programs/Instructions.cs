namespace Machina;

/// <summary>Reads Machina instruction text (as written by <c>ToInstruction()</c> or a <c>.machina</c> program) into actions.</summary>
public static class Instructions
{
    /// <summary>
    /// All actions in <paramref name="text"/>, in order. Statements look like <c>MoveTo(400, 300, 500);</c>; several may share a
    /// line; <c>//</c> starts a comment. Throws with the line and column of the first problem.
    /// </summary>
    /// <exception cref="InstructionParseException">The text is malformed or a value is not acceptable.</exception>
    public static IReadOnlyList<RobotAction> Parse(string text)
    {
        var actions = new List<RobotAction>();
        var parser = new InstructionParser(text);
        while (parser.Next() is RobotAction action)
        {
            actions.Add(action);
        }
        return actions;
    }

    /// <summary>The actions of an instruction file (UTF-8, with or without byte order mark).</summary>
    public static IReadOnlyList<RobotAction> ParseFile(string path) => Parse(File.ReadAllText(path));

    /// <summary>Reads actions one by one, for very long programs; parsing stops at the first problem.</summary>
    /// <exception cref="ArgumentNullException"><paramref name="text"/> is null (thrown at once, not when enumerating).</exception>
    public static IEnumerable<RobotAction> Enumerate(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        return Read(text);
    }

    /// <summary>Each enumeration reads the text from its start with a parser of its own.</summary>
    private static IEnumerable<RobotAction> Read(string text)
    {
        var parser = new InstructionParser(text);
        while (parser.Next() is RobotAction action)
        {
            yield return action;
        }
    }
}

namespace Machina.Benchmarks;

/// <summary>
/// Inputs shared by several scenarios, built once per size: a robot holding a toolpath of relative moves (what a designer
/// streams to a 3D printer or a mill) and the same kind of program as instruction text.
/// </summary>
internal sealed class Workloads
{
    private static readonly Vector[] Steps = [new(10, 0, 0), new(0, 10, 0.5), new(-10, 0, 0), new(0, -10, 0.5)];

    private readonly Dictionary<int, Robot> _toolpaths = [];
    private readonly Dictionary<int, string> _texts = [];

    /// <summary>Issues a speed, a start position and <paramref name="moves"/> relative moves (a square spiral rising 1 mm per lap).</summary>
    public static Robot IssueToolpath(string brand, int moves)
    {
        var bot = Robot.Create("Bench", brand);
        bot.SpeedTo(100);
        bot.MoveTo(300, 0, 500);
        for (int i = 0; i < moves; i++)
        {
            bot.Move(Steps[i & 3]);
        }
        return bot;
    }

    /// <summary>A robot (ABB, though it compiles to any language) holding a toolpath of <paramref name="moves"/> moves; kept for reuse.</summary>
    public Robot Toolpath(int moves)
    {
        if (!_toolpaths.TryGetValue(moves, out Robot? bot))
        {
            bot = IssueToolpath("ABB", moves);
            _toolpaths[moves] = bot;
        }
        return bot;
    }

    /// <summary>
    /// An instruction file of <paramref name="lines"/> lines, as a <c>.machina</c> program looks: mostly moves with decimals,
    /// with speed changes, waits, messages with quotes, comments and rotations mixed in. Kept for reuse.
    /// </summary>
    public string InstructionText(int lines)
    {
        if (!_texts.TryGetValue(lines, out string? text))
        {
            var builder = new System.Text.StringBuilder(lines * 24);
            var random = new Random(6);
            for (int i = 0; i < lines; i++)
            {
                builder.Append(Line(i, random)).Append('\n');
            }
            text = builder.ToString();
            _texts[lines] = text;
        }
        return text;
    }

    /// <summary>Writes the same instruction program as <see cref="InstructionText"/> straight into a file, for sizes too large to hold as text.</summary>
    public static void WriteInstructionFile(string path, int lines)
    {
        using var writer = new StreamWriter(path, append: false, new System.Text.UTF8Encoding(false), bufferSize: 1 << 16);
        var random = new Random(6);
        writer.Write(new ActionTranslation(new Vector(300, 0, 500), false).ToInstruction());
        writer.Write('\n');
        for (int i = 1; i < lines; i++)
        {
            writer.Write(Line(i, random));
            writer.Write('\n');
        }
    }

    public static string Line(int i, Random random)
    {
        double R(double scale) => Math.Round((random.NextDouble() - 0.5) * scale, 3);
        return (i % 50) switch
        {
            0 => new ActionSpeed(50 + (i % 7) * 10, false).ToInstruction(),
            10 => "// layer " + i / 50,
            20 => new ActionWait(250).ToInstruction(),
            30 => new ActionMessage($"Reached \"point\" {i}").ToInstruction(),
            40 => new ActionRotation(new Vector(0, 0, 1), R(10), true).ToInstruction(),
            45 => new ActionTranslation(new Vector(300 + R(100), R(100), 500 + R(100)), false).ToInstruction(),
            _ => new ActionTranslation(new Vector(R(20), R(20), R(2)), true).ToInstruction(),
        };
    }
}

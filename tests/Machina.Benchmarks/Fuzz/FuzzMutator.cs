using System.Text;

namespace Machina.Benchmarks.Fuzz;

/// <summary>
/// Makes hostile programs for an interpreter: a seed program (a golden file, a driver, a snippet) mutated a few times (spans
/// cut, doubled or swapped, tokens of the language inserted, numbers made extreme, a bracket or sign repeated thousands of times),
/// or a program generated from the language's templates with random expressions. Deterministic for a seed.
/// </summary>
internal sealed class FuzzMutator(Random random, IReadOnlyList<string> tokens, Func<Random, string> generate)
{
    private static readonly string[] Extremes =
        ["0", "-1", "2147483647", "-2147483648", "2147483648", "46341", "100000", "1E308", "-1E308", "1E-320", "0.0", "9E9", "1000000", "3"];

    /// <summary>A new case: mostly a mutated seed, sometimes a generated program.</summary>
    public string Next(IReadOnlyList<string> seeds)
    {
        if (random.Next(5) == 0)
        {
            return generate(random);
        }
        string text = seeds[random.Next(seeds.Count)];
        int mutations = 1 + random.Next(4);
        for (int i = 0; i < mutations; i++)
        {
            text = Mutate(text);
        }
        return text;
    }

    private string Mutate(string text)
    {
        if (text.Length == 0)
        {
            return tokens[random.Next(tokens.Count)];
        }
        int at = random.Next(text.Length);
        int length = Math.Min(text.Length - at, 1 + random.Next(Math.Min(200, text.Length)));
        return random.Next(9) switch
        {
            0 => text.Remove(at, length),
            1 => text.Insert(at, text.Substring(at, length)),
            2 => text.Insert(at, tokens[random.Next(tokens.Count)]),
            3 => text.Insert(at, " " + Extremes[random.Next(Extremes.Length)] + " "),
            4 => ReplaceNumber(text, at),
            5 => text.Insert(at, string.Concat(Enumerable.Repeat(tokens[random.Next(tokens.Count)], 1 + random.Next(random.Next(2) == 0 ? 50 : 5_000)))),
            6 => SwapLines(text),
            7 => text.Insert(at, RandomText(1 + random.Next(20))),
            _ => DuplicateLine(text, at),
        };
    }

    private string ReplaceNumber(string text, int at)
    {
        int start = at;
        while (start < text.Length && !char.IsAsciiDigit(text[start]))
        {
            start++;
        }
        if (start == text.Length)
        {
            return text;
        }
        int end = start;
        while (end < text.Length && (char.IsAsciiDigit(text[end]) || text[end] == '.'))
        {
            end++;
        }
        return string.Concat(text.AsSpan(0, start), Extremes[random.Next(Extremes.Length)], text.AsSpan(end));
    }

    private string SwapLines(string text)
    {
        string[] lines = text.Split('\n');
        if (lines.Length < 2)
        {
            return text;
        }
        int a = random.Next(lines.Length), b = random.Next(lines.Length);
        (lines[a], lines[b]) = (lines[b], lines[a]);
        return string.Join('\n', lines);
    }

    private string DuplicateLine(string text, int at)
    {
        int start = text.LastIndexOf('\n', Math.Max(0, at - 1)) + 1;
        int end = text.IndexOf('\n', at);
        end = end < 0 ? text.Length : end + 1;
        string line = text[start..end];
        int copies = 1 + random.Next(random.Next(2) == 0 ? 3 : 200);
        return text.Insert(end, string.Concat(Enumerable.Repeat(line.EndsWith('\n') ? line : line + "\n", copies)));
    }

    private string RandomText(int length)
    {
        var text = new StringBuilder(length);
        for (int i = 0; i < length; i++)
        {
            text.Append((char)random.Next(random.Next(4) == 0 ? 256 : 128));
        }
        return text.ToString();
    }

    /// <summary>A random expression of <paramref name="depth"/> levels at most over <paramref name="leaves"/> and <paramref name="operators"/>.</summary>
    public static string Expression(Random random, int depth, string[] leaves, string[] operators, string[] unary)
    {
        if (depth <= 0 || random.Next(4) == 0)
        {
            return random.Next(3) == 0 ? Extremes[random.Next(Extremes.Length)] : leaves[random.Next(leaves.Length)];
        }
        return random.Next(6) switch
        {
            0 => unary[random.Next(unary.Length)] + Expression(random, depth - 1, leaves, operators, unary),
            1 => "(" + Expression(random, depth - 1, leaves, operators, unary) + ")",
            _ => Binary(random, depth, leaves, operators, unary),
        };
    }

    // One side goes deep, the other stays shallow: the expression grows with its depth, not exponentially.
    private static string Binary(Random random, int depth, string[] leaves, string[] operators, string[] unary)
    {
        string deep = Expression(random, depth - 1, leaves, operators, unary);
        string shallow = Expression(random, Math.Min(depth - 1, 2), leaves, operators, unary);
        string op = " " + operators[random.Next(operators.Length)] + " ";
        return random.Next(2) == 0 ? deep + op + shallow : shallow + op + deep;
    }

    /// <summary>A depth for a generated expression: mostly small, sometimes past the nesting budget.</summary>
    public static int Depth(Random random) => random.Next(10) switch
    {
        0 => 100 + random.Next(200),
        1 or 2 => 10 + random.Next(20),
        _ => 1 + random.Next(6),
    };
}

using System.Text;

namespace Machina.Tests.Reliability;

/// <summary>Deterministic input generators for the fuzz tests: random text over an alphabet, and mutations of valid inputs.</summary>
internal static class Fuzz
{
    /// <summary>Cases per fuzz test.</summary>
    public const int Cases = 100_000;

    /// <summary>Longest a whole fuzz test may take before it counts as a hang (generous: the machine is shared).</summary>
    public static readonly TimeSpan HangLimit = TimeSpan.FromSeconds(180);

    /// <summary>Random bytes, most drawn from <paramref name="alphabet"/>, some from anywhere (NUL, high bytes, UTF-8 pieces).</summary>
    public static byte[] Random(Random random, byte[] alphabet, int maxLength)
    {
        var bytes = new byte[random.Next(maxLength + 1)];
        for (int i = 0; i < bytes.Length; i++)
        {
            bytes[i] = random.Next(8) == 0 ? (byte)random.Next(256) : alphabet[random.Next(alphabet.Length)];
        }
        return bytes;
    }

    /// <summary>A valid input changed 1 to 4 times: a byte replaced, inserted or deleted, a piece repeated, or the end cut.</summary>
    public static byte[] Mutate(Random random, byte[] valid, byte[] alphabet)
    {
        var bytes = new List<byte>(valid);
        int changes = 1 + random.Next(4);
        for (int c = 0; c < changes; c++)
        {
            int at = bytes.Count == 0 ? 0 : random.Next(bytes.Count);
            byte any = random.Next(4) == 0 ? (byte)random.Next(256) : alphabet[random.Next(alphabet.Length)];
            switch (random.Next(5))
            {
                case 0 when bytes.Count > 0:
                    bytes[at] = any;
                    break;
                case 1:
                    bytes.Insert(at, any);
                    break;
                case 2 when bytes.Count > 0:
                    bytes.RemoveAt(at);
                    break;
                case 3 when bytes.Count > 0:
                    int length = random.Next(1, Math.Min(16, bytes.Count - at) + 1);
                    bytes.InsertRange(at, bytes.GetRange(at, length));
                    break;
                default:
                    bytes.RemoveRange(at, bytes.Count - at);
                    break;
            }
        }
        return [.. bytes];
    }

    /// <summary>The i-th case: half random, half mutated from the valid inputs.</summary>
    public static byte[] Case(Random random, int i, string[] valid, byte[] alphabet, int maxLength) =>
        i % 2 == 0 ? Random(random, alphabet, maxLength) : Mutate(random, Encoding.UTF8.GetBytes(valid[random.Next(valid.Length)]), alphabet);

    /// <summary>Runs <paramref name="body"/> on a worker and fails when it does not finish within <see cref="HangLimit"/>.</summary>
    public static async Task RunBoundedAsync(Action body) => await Task.Run(body).WaitAsync(HangLimit);
}

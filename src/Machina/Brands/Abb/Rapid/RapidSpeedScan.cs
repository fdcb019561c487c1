using System.Buffers;
using System.Globalization;

namespace Machina;

/// <summary>
/// A guess at the speeds a RAPID module declares, from the raw characters of an instruction text (no parse): the text's
/// only statements that declare (<see cref="RapidPlan.WordsThatDeclare"/>) are <c>SpeedTo(number)</c>, and the motions move
/// first at the start speed (unless the text starts with a <c>SpeedTo</c>), then at each of those speeds in order. The
/// guess is checked against what the writing pass met (<see cref="RapidPlan.DeclaresAs"/>); when it is wrong the module is
/// written again another way, so a wrong guess costs time, never a byte.
/// </summary>
internal sealed class RapidSpeedScan
{
    private const string SpeedTo = "SpeedTo(";

    /// <summary>Characters kept from one block to the next, so that a statement cut between two blocks is read whole.</summary>
    private const int Overlap = 64;

    private static readonly SearchValues<char> Anchors = SearchValues.Create([.. RapidPlan.WordsThatDeclare.Select(w => w[InstructionSource.Anchor(w)]).Distinct()]);

    /// <summary>The numbers of the <c>SpeedTo</c> statements, in the order of the text.</summary>
    internal List<double> Speeds { get; } = [];

    /// <summary>True when something stands before the first <c>SpeedTo</c> (a motion at the start speed, the guess says).</summary>
    internal bool StartSpeedMoves { get; private set; } = true;

    /// <summary>
    /// The guess for the text <paramref name="source"/> reads, or null when it names a declaring word otherwise. The source's
    /// token is checked per block read (a scan of a long text stops when the compile is cancelled, as
    /// <see cref="InstructionSource.MayContain"/> does).
    /// </summary>
    /// <exception cref="OperationCanceledException">The source's token was cancelled.</exception>
    internal static RapidSpeedScan? Of(InstructionSource source)
    {
        var scan = new RapidSpeedScan();
        char[] buffer = new char[(1 << 16) + Overlap];
        int kept = 0;
        bool atStart = true;
        using TextReader reader = source.OpenText();
        while (true)
        {
            int read = reader.ReadBlock(buffer, kept, buffer.Length - kept);
            source.CancellationToken.ThrowIfCancellationRequested();
            bool end = read < buffer.Length - kept;
            ReadOnlySpan<char> text = buffer.AsSpan(0, kept + read);
            // Words that start at or after the limit are read with the next block (they may be cut here).
            int limit = end ? text.Length : text.Length - Overlap;
            for (int at = text.IndexOfAny(Anchors); at >= 0;)
            {
                int skip = scan.Read(text, at, limit, atStart);
                if (skip < 0)
                {
                    return null;
                }
                int next = text[(at + skip)..].IndexOfAny(Anchors);
                at = next < 0 ? -1 : at + skip + next;
            }
            if (end)
            {
                return scan;
            }
            atStart = atStart && text[..limit].IsWhiteSpace();
            text[limit..].CopyTo(buffer);
            kept = Overlap;
        }
    }

    /// <summary>
    /// Reads what stands at <paramref name="at"/> (an anchor character): the characters to skip, or -1 when a declaring
    /// word that starts before <paramref name="limit"/> stands there other than as <c>SpeedTo(number)</c>.
    /// </summary>
    private int Read(ReadOnlySpan<char> text, int at, int limit, bool atStart)
    {
        foreach (string word in RapidPlan.WordsThatDeclare)
        {
            int begin = at - InstructionSource.Anchor(word);
            if (begin >= 0 && begin < limit && text[begin..].StartsWith(word, StringComparison.Ordinal))
            {
                if (begin != at || !text[at..].StartsWith(SpeedTo, StringComparison.Ordinal))
                {
                    return -1;
                }
                ReadOnlySpan<char> rest = text[(at + SpeedTo.Length)..];
                int close = rest[..Math.Min(rest.Length, Overlap - SpeedTo.Length)].IndexOf(')');
                if (close < 0 || !double.TryParse(rest[..close], NumberStyles.Float, CultureInfo.InvariantCulture, out double speed))
                {
                    return -1;
                }
                if (Speeds.Count == 0)
                {
                    StartSpeedMoves = !(atStart && text[..at].IsWhiteSpace());
                }
                Speeds.Add(speed);
                return SpeedTo.Length + close;
            }
        }
        return 1;
    }
}

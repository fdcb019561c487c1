using System.Buffers;
using System.Collections;
using System.Collections.Concurrent;
using System.Runtime.ExceptionServices;

namespace Machina;

/// <summary>
/// The actions of an instruction text that is read again from its start for every pass a compiler makes, so that no pass
/// holds the whole program: memory stays the same for ten lines or ten million. Actions get the ids a robot would give them
/// (1, 2, 3, … in order), and the source remembers where the action it returned last was written, for warnings and errors.
/// Each pass reads and parses on a thread of its own, a few thousand statements ahead of the compiler (at most
/// <see cref="BatchesAhead"/> batches), so that on two or more cores parsing and compiling overlap; errors still surface
/// exactly where the statement is reached.
/// </summary>
internal sealed class InstructionSource(Func<TextReader> open, CancellationToken cancellationToken) : IEnumerable<RobotAction>
{
    /// <summary>
    /// Statements per batch handed from the reading thread to the compiler: each hand-over wakes a thread, which cost about
    /// 5 % of a 10^6-line compile with batches of 512 (docs/performance.md, "The cold path, third session"). The statements
    /// of the batches in flight are what every collection of the first generation finds alive and copies: with the tool's
    /// 4 MB generation 0 (Machina.Cli.csproj), batches of 4096 made the collector 12.6 % of a 10^6-line URScript compile,
    /// 1024 make it 4.8 % (and the peak 23 MB instead of 31 MB; docs/performance.md, session 26).
    /// </summary>
    internal const int BatchSize = 1024;

    /// <summary>
    /// Batches the reading thread may be ahead. Two keep both cores busy; four held some 2–6 MB more at the peak of a
    /// 10^6-line compile for no gain in time (docs/performance.md, "The cold path, fifth session").
    /// </summary>
    internal const int BatchesAhead = 2;

    /// <summary>
    /// Positions of the last actions read, by id (a ring): a compiler may warn about an action it met a little earlier (a UR blend
    /// that only the next motion shows to be too large), and the warning must still point at that action's statement.
    /// </summary>
    internal const int PositionsKept = 1024;

    private readonly (int Id, int Line, int Column)[] _recent = new (int, int, int)[PositionsKept];

    /// <summary>Number of actions in the text, known after the first complete pass (0 before).</summary>
    internal int Count { get; private set; }

    /// <summary>
    /// The line and column of the action with id <paramref name="actionId"/> if it is one of the last <see cref="PositionsKept"/>
    /// actions returned, else null.
    /// </summary>
    internal (int Line, int Column)? PositionOf(int actionId)
    {
        if (actionId <= 0)
        {
            return null;
        }
        (int id, int line, int column) = _recent[actionId % PositionsKept];
        return id == actionId ? (line, column) : null;
    }

    /// <summary>The error for an action that cannot be applied: an instruction error at the action's position.</summary>
    internal InstructionParseException Refused(RobotAction action, string reason)
    {
        // The action being compiled is the newest in the ring, so its position is found there too.
        (int Line, int Column) at = PositionOf(action.Id) ?? (0, 0);
        return new InstructionParseException(at.Line, at.Column, $"cannot apply \"{action.ToInstruction()}\": {reason}");
    }

    /// <summary>
    /// False when the text contains none of <paramref name="words"/> anywhere (in a statement, a comment or a string): a
    /// scan of the raw characters, far cheaper than a parse, that lets a compiler skip a pass whose result it already knows.
    /// </summary>
    internal bool MayContain(IReadOnlyList<string> words)
    {
        int longest = words.Max(w => w.Length);
        // Each word is looked for by one character of it that toolpaths rarely hold (its anchor, see Anchor): one vectorised
        // search per block finds the places where any word may stand, and only there are words compared. A toolpath that
        // names none of the words is searched once, not once per word.
        int[] anchors = [.. words.Select(Anchor)];
        SearchValues<char> anchorChars = SearchValues.Create([.. words.Select((w, i) => w[anchors[i]]).Distinct()]);
        char[] buffer = new char[(1 << 16) + longest];
        int kept = 0;
        using TextReader reader = open();
        int read;
        while ((read = reader.ReadBlock(buffer, kept, buffer.Length - kept)) > 0)
        {
            cancellationToken.ThrowIfCancellationRequested();
            ReadOnlySpan<char> text = buffer.AsSpan(0, kept + read);
            for (int at = text.IndexOfAny(anchorChars); at >= 0;)
            {
                for (int i = 0; i < words.Count; i++)
                {
                    string word = words[i];
                    int begin = at - anchors[i];
                    if (text[at] == word[anchors[i]] && begin >= 0 && text[begin..].StartsWith(word, StringComparison.Ordinal))
                    {
                        return true;
                    }
                }
                int next = text[(at + 1)..].IndexOfAny(anchorChars);
                at = next < 0 ? -1 : at + 1 + next;
            }
            // Keeps the end of this block so that a word cut between two blocks is still found.
            kept = Math.Min(longest - 1, text.Length);
            text[^kept..].CopyTo(buffer);
        }
        return false;
    }

    /// <summary>The text itself, from its start, for a compiler's own scan of it (the caller disposes the reader).</summary>
    internal TextReader OpenText() => open();

    /// <summary>The token that stops the reading: a compiler's own scan of the text (<see cref="OpenText"/>) checks it per block, as <see cref="MayContain"/> does.</summary>
    internal CancellationToken CancellationToken => cancellationToken;

    /// <summary>The letters of the motion instructions' names (Move, MoveTo, Rotate, RotateTo, Transform, Axes, …): a toolpath is mostly these.</summary>
    private const string ToolpathLetters = "MoveToRtaAxsTrnfm";

    /// <summary>
    /// Where <paramref name="word"/> is looked for by <see cref="MayContain"/> (and RAPID's speed scan): its first character that
    /// is not a letter of the motion instructions' names (<c>Tool</c> by its <c>l</c>, <c>Read</c> by its <c>d</c>), else its first.
    /// </summary>
    internal static int Anchor(string word)
    {
        int at = word.AsSpan().IndexOfAnyExcept(ToolpathLetters);
        return at < 0 ? 0 : at;
    }

    /// <summary>Parsed statements with their positions, and the error that ended the text after them, if any.</summary>
    private sealed class Batch
    {
        internal readonly RobotAction[] Actions = new RobotAction[BatchSize];
        internal readonly int[] Lines = new int[BatchSize];
        internal readonly int[] Columns = new int[BatchSize];
        internal int Count;
        internal ExceptionDispatchInfo? Error;
    }

    /// <inheritdoc/>
    public IEnumerator<RobotAction> GetEnumerator()
    {
        using var stop = CancellationTokenSource.CreateLinkedTokenSource(cancellationToken);
        using var batches = new BatchHandOff<Batch>(BatchesAhead, stop.Token);
        // Batches the compiler is done with go back to the reading thread, so that a pass allocates only a few.
        var free = new ConcurrentQueue<Batch>();
        Task reading = Task.Factory.StartNew(() => Read(batches, free, stop.Token), stop.Token, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        try
        {
            int id = 0;
            while (batches.TryTake(out Batch batch, cancellationToken))
            {
                for (int i = 0; i < batch.Count; i++)
                {
                    RobotAction action = batch.Actions[i];
                    action.Id = ++id;
                    _recent[id % PositionsKept] = (id, batch.Lines[i], batch.Columns[i]);
                    yield return action;
                }
                batch.Error?.Throw();
                batch.Count = 0;
                free.Enqueue(batch);
            }
            cancellationToken.ThrowIfCancellationRequested();
            Count = id;
        }
        finally
        {
            // Stops the reading thread if the compiler stopped early (an error, or cancellation), and waits for it.
            stop.Cancel();
            try
            {
                reading.Wait(CancellationToken.None);
            }
            catch (AggregateException)
            {
                // Cancelled while handing over a batch: nothing to report.
            }
        }
    }

    /// <summary>
    /// The reading thread: parses the text into batches. Whatever stops it (the end, a parse error, a file that cannot be
    /// read) is handed over after the statements before it, so the compiler meets it in order; nothing is silently cut.
    /// </summary>
    private void Read(BatchHandOff<Batch> batches, ConcurrentQueue<Batch> free, CancellationToken stop)
    {
        var batch = new Batch();
        try
        {
            try
            {
                using TextReader reader = open();
                var parser = new InstructionReader(reader);
                while (parser.Next() is RobotAction action)
                {
                    batch.Actions[batch.Count] = action;
                    batch.Lines[batch.Count] = parser.Line;
                    batch.Columns[batch.Count] = parser.Column;
                    if (++batch.Count == BatchSize)
                    {
                        batches.Add(batch);
                        batch = free.TryDequeue(out Batch? done) ? done : new Batch();
                    }
                }
            }
            catch (Exception ex) when (ex is not OperationCanceledException || !stop.IsCancellationRequested)
            {
                batch.Error = ExceptionDispatchInfo.Capture(ex);
            }
            if (batch.Count > 0 || batch.Error is not null)
            {
                batches.Add(batch);
            }
        }
        catch (OperationCanceledException) when (stop.IsCancellationRequested)
        {
            // The compiler stopped reading.
        }
        finally
        {
            batches.Complete();
        }
    }

    IEnumerator IEnumerable.GetEnumerator() => GetEnumerator();
}

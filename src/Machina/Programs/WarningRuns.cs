using System.Text;

namespace Machina;

/// <summary>
/// The lines of a program file on their way to it, counted, with the warning comments of consecutive motions grouped: the
/// first motion of a run that draws one warning keeps its comment just before it, as always; the motions after it in a row
/// that draw the same warning get none, and one comment after the run names its first and last lines and how many motions
/// it holds. A program of 10^6 short moves says so twice, not 10^6 times (a reader cannot use the copies).
/// </summary>
/// <remarks>
/// Lines stream straight to the file (nothing is held back or rewritten). The warnings themselves still reach the compile job
/// one by one (<see cref="CompileJob.Warnings"/>).
/// </remarks>
internal sealed class WarningRuns(LineSink file, string commentPrefix) : LineSink
{
    // The run under way: its warning's kind, how many motions, the lines of its first and last motion.
    private string? _kind;
    private int _count;
    private int _firstLine;
    private int _lastLine;

    // The warnings of the motion about to be written that do not continue the run: their kinds, and their lines one after
    // another in one reused buffer (a program of short moves gives one such line every other motion: a string each was
    // most of what a 10^6-line URScript compile allocated).
    private readonly List<(string Kind, int Start, int Length)> _pending = [];
    private char[] _pendingText = new char[1024];
    private readonly StringBuilder _closing = new(128);
    private int _pendingChars;
    private bool _continues;

    // The kind of the first warning of the motion about to be written that went straight to the file (no run was under way).
    private string? _started;

    // A warning line of bytes given while a run is under way: it may go on the run (not written) or wait for the run's end.
    private byte[] _asciiWarning = new byte[320];

    /// <summary>Lines that reached the file so far: the next line written is number <see cref="LinesWritten"/> + 1.</summary>
    internal int LinesWritten { get; private set; }

    /// <summary>
    /// Gives a warning comment of the motion about to be written (before <see cref="Motion"/>): <paramref name="kind"/> names
    /// the warning (the same kind on consecutive motions makes a run), <paramref name="line"/> is the whole comment line.
    /// </summary>
    /// <remarks>
    /// With no run under way nothing can come before the line (no run's closing comment), so it goes to the file at once, not
    /// through the pending buffer: lines added between <see cref="Warn"/> and <see cref="Motion"/> would come after it.
    /// </remarks>
    internal void Warn(string kind, ReadOnlySpan<char> line)
    {
        if (Continues(kind))
        {
            _continues = true; // the run goes on: this copy is not written
            return;
        }
        if (_count == 0)
        {
            Add(line);
            _started ??= kind;
            return;
        }
        if (_pendingChars + line.Length > _pendingText.Length)
        {
            Array.Resize(ref _pendingText, Math.Max(_pendingText.Length * 2, _pendingChars + line.Length));
        }
        line.CopyTo(_pendingText.AsSpan(_pendingChars));
        _pending.Add((kind, _pendingChars, line.Length));
        _pendingChars += line.Length;
    }

    /// <summary>
    /// Room for a warning comment line of ASCII bytes, at least <paramref name="most"/> long, for <see cref="EndWarnAscii"/>: with no
    /// run under way the file's own room (<see cref="LineSink.BeginAscii"/>: the line is written once, in place), else a buffer of this sink's.
    /// </summary>
    internal Span<byte> BeginWarnAscii(int most)
    {
        if (_count == 0)
        {
            return BeginAscii(most);
        }
        if (_asciiWarning.Length < most)
        {
            _asciiWarning = new byte[most];
        }
        return _asciiWarning.AsSpan(0, most);
    }

    /// <summary>Gives the first <paramref name="length"/> bytes of <see cref="BeginWarnAscii"/>'s room as <see cref="Warn"/> gives a line.</summary>
    internal void EndWarnAscii(string kind, int length)
    {
        if (_count == 0)
        {
            EndAscii(length);
            _started ??= kind;
            return;
        }
        if (Continues(kind))
        {
            _continues = true;
            return;
        }
        Span<char> line = length <= 512 ? stackalloc char[length] : new char[length];
        System.Text.Ascii.ToUtf16(_asciiWarning.AsSpan(0, length), line, out _);
        Warn(kind, line);
    }

    /// <summary>True when a warning of <paramref name="kind"/> given now would go on the run under way (its line would not be written).</summary>
    internal bool Continues(string kind) => _count > 0 && kind == _kind;

    /// <summary>A motion begins: its warnings were given with <see cref="Warn"/>; its lines follow.</summary>
    internal void Motion()
    {
        if (_continues)
        {
            _count++;
            // The motion's first line comes after the run's closing comment and its own other warnings, when it has them.
            _lastLine = LinesWritten + 1 + (_pending.Count > 0 ? 1 + _pending.Count : 0);
            _continues = false;
            if (_pending.Count == 0)
            {
                return;
            }
        }
        EndRun();
        foreach ((_, int start, int length) in _pending)
        {
            Add(_pendingText.AsSpan(start, length));
        }
        if (_pending.Count > 0)
        {
            (_kind, _count) = (_pending[0].Kind, 1);
            _firstLine = _lastLine = LinesWritten + 1;
            _pending.Clear();
            _pendingChars = 0;
        }
        else if (_started is not null)
        {
            // Its warnings went to the file at once (no run was under way): the run starts here all the same.
            (_kind, _count) = (_started, 1);
            _firstLine = _lastLine = LinesWritten + 1;
        }
        _started = null;
    }

    /// <summary>Ends the run under way (also called after the last motion): a run of two motions or more gets its closing comment.</summary>
    internal void EndRun()
    {
        if (_count > 1)
        {
            // One reused builder, the numbers formatted into it: no string per run.
            _closing.Clear().Append(commentPrefix)
                .Append(Num.Inv, $"WARNING: the same warning for {_count} motions in a row, lines {_firstLine} to {_lastLine}")
                .Append(" (written once, above the first)");
            Add(_closing);
        }
        (_kind, _count) = (null, 0);
    }

    private void Write(string line)
    {
        file.Add(line);
        LinesWritten++;
    }

    internal override void Add(string line) => Write(line);

    internal override void Add(StringBuilder line)
    {
        file.Add(line);
        LinesWritten++;
    }

    internal override void Add(ReadOnlySpan<char> line)
    {
        file.Add(line);
        LinesWritten++;
    }

    internal override Span<byte> BeginAscii(int most) => file.BeginAscii(most);

    internal override void EndAscii(int length)
    {
        file.EndAscii(length);
        LinesWritten++;
    }
}

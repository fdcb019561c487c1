namespace Machina.Simulation.UrScript;

/// <summary>
/// Splits the text that arrives on a script port into programs, as the Script Manual describes: a program starts with <c>def</c>
/// or <c>sec</c> in column 1 and is complete at its <c>end</c> in column 1 (no line break needed after it); the call line that
/// often follows a definition belongs to it and is skipped; any other complete line outside a definition is a one-line program.
/// Text is scanned once, however it is chunked (a 10^5-line program arriving in pieces is not re-read from its start).
/// </summary>
internal sealed class UrScriptIntake
{
    private char[] _buffer = new char[4096];
    private int _length;
    private int _scanAt;
    private int _programStart = -1;
    private string? _startedName;

    /// <summary>Characters held (received and not yet taken as a program).</summary>
    public int Length => _length;

    /// <summary>Adds received text.</summary>
    public void Append(string text)
    {
        if (_length + text.Length > _buffer.Length)
        {
            Array.Resize(ref _buffer, Math.Max(_buffer.Length * 2, _length + text.Length));
        }
        text.CopyTo(0, _buffer, _length, text.Length);
        _length += text.Length;
    }

    /// <summary>Forgets everything held.</summary>
    public void Clear()
    {
        _length = 0;
        _scanAt = 0;
        _programStart = -1;
    }

    /// <summary>The next complete program, or null until more text arrives.</summary>
    public string? TakeProgram()
    {
        while (true)
        {
            ReadOnlySpan<char> rest = _buffer.AsSpan(_scanAt, _length - _scanAt);
            if (rest.IsEmpty)
            {
                return null;
            }
            int newline = rest.IndexOf('\n');
            bool complete = newline >= 0;
            int next = _scanAt + (complete ? newline + 1 : rest.Length);
            ReadOnlySpan<char> raw = complete ? rest[..newline] : rest;
            if (_programStart >= 0 && (raw.IsEmpty || raw[0] != 'e'))
            {
                // Inside a program only an "end" in column 1 matters: the other lines are passed over without making a string.
                if (!complete)
                {
                    return null;
                }
                _scanAt = next;
                continue;
            }
            string line = new string(raw).TrimEnd('\r');
            string code = StripComment(line).TrimEnd();
            if (_programStart < 0)
            {
                if (_startedName is not null && CallOfStarted(line, code, complete) is int call)
                {
                    if (call == 0)
                    {
                        return null; // what has arrived may still become the call: wait for more
                    }
                    // The call of the program just taken belongs to it, line break or not: the original Machina.NET host
                    // sends its driver without a final line break and its stop program later on the same connection.
                    _startedName = null;
                    Consume(_scanAt + call);
                    continue;
                }
                if (code.Trim().Length == 0)
                {
                    if (!complete)
                    {
                        return null;
                    }
                    Consume(next);
                    continue;
                }
                if (code.StartsWith("def ", StringComparison.Ordinal) || code.StartsWith("sec ", StringComparison.Ordinal))
                {
                    _programStart = _scanAt;
                }
                else if (complete)
                {
                    Consume(next);
                    if (_startedName is not null && code.Trim() == _startedName + "()")
                    {
                        _startedName = null;
                        continue;
                    }
                    return line;
                }
                else
                {
                    return null;
                }
            }
            else if (code == "end" && line.Length > 0 && line[0] == 'e')
            {
                string program = new(_buffer, _programStart, next - _programStart);
                Consume(next);
                string header = program.TrimStart();
                int paren = header.IndexOf('(', StringComparison.Ordinal);
                _startedName = paren > 4 ? header[4..paren].Trim() : null;
                return program;
            }
            if (!complete)
            {
                return null; // scanned again, whole, when its line break arrives
            }
            _scanAt = next;
        }
    }

    /// <summary>
    /// How many characters of <paramref name="line"/> are the call of the program just taken (<c>name()</c>, after any
    /// indentation): null when the line is not that call, 0 when it may still become it.
    /// </summary>
    private int? CallOfStarted(string line, string code, bool complete)
    {
        string call = _startedName + "()";
        string trimmed = code.TrimStart();
        int indent = line.Length - line.TrimStart().Length;
        if (trimmed.StartsWith(call, StringComparison.Ordinal))
        {
            return indent + call.Length;
        }
        return !complete && trimmed.Length > 0 && call.StartsWith(trimmed, StringComparison.Ordinal) ? 0 : null;
    }

    /// <summary>Drops the first <paramref name="count"/> characters (taken or skipped).</summary>
    private void Consume(int count)
    {
        Array.Copy(_buffer, count, _buffer, 0, _length - count);
        _length -= count;
        _scanAt = 0;
        _programStart = -1;
    }

    /// <summary>The line without its comment (a <c>#</c> outside quotes and what follows).</summary>
    internal static string StripComment(string line)
    {
        bool quoted = false;
        for (int i = 0; i < line.Length; i++)
        {
            if (line[i] == '"')
            {
                quoted = !quoted;
            }
            else if (line[i] == '#' && !quoted)
            {
                return line[..i];
            }
        }
        return line;
    }
}

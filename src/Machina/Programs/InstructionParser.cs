namespace Machina;

/// <summary>
/// Reads Machina instruction text: statements like <c>MoveTo(400, 300, 500);</c>, any number per line, separated by
/// semicolons or line breaks, with <c>//</c> comments (also between arguments) and double-quoted strings (<c>\"</c>, <c>\\</c>, <c>\n</c> escapes).
/// </summary>
internal sealed class InstructionParser
{
    private readonly char[] _text;
    private readonly int _length;
    private readonly InstructionArgs _args;
    private readonly bool _final;
    private int _pos;
    private int _line = 1;
    private int _lineStart;
    private string _lastName = "";
    private InstructionCatalog.Overload[] _lastOverloads = [];
    private string _otherName = "";
    private InstructionCatalog.Overload[] _otherOverloads = [];

    internal InstructionParser(string text)
        : this((text ?? throw new ArgumentNullException(nameof(text))).ToCharArray(), text.Length, new InstructionArgs(), firstLine: 1, start: 0, isFinal: true)
    {
    }

    /// <summary>
    /// A parser for one piece of a longer text (see <see cref="InstructionReader"/>): the first <paramref name="length"/>
    /// characters of <paramref name="text"/> (the reader's own buffer, read in place) start at the beginning of line
    /// <paramref name="firstLine"/> and parsing starts at <paramref name="start"/>. When
    /// <paramref name="isFinal"/> is false more text follows, and a statement cut by the end of this piece throws
    /// <see cref="StatementCutException"/> instead of a parse error.
    /// </summary>
    internal InstructionParser(char[] text, int length, InstructionArgs args, int firstLine, int start, bool isFinal)
    {
        _text = text;
        _length = length;
        _args = args;
        _line = firstLine;
        _pos = start;
        _final = isFinal;
    }

    private int Column => _pos - _lineStart + 1;

    /// <summary>The line the parser has reached (after the last statement read).</summary>
    internal int Line => _line;

    /// <summary>Line (from 1) of the statement read last.</summary>
    internal int StatementLine { get; private set; }

    /// <summary>Column (from 1) of the statement read last.</summary>
    internal int StatementColumn { get; private set; }

    /// <summary>Offset in the text of the start of the line where the statement read last begins.</summary>
    internal int StatementLineStart { get; private set; }

    /// <summary>The next action, or null at the end of the text.</summary>
    /// <exception cref="InstructionParseException">The text is malformed, or a value is not acceptable.</exception>
    internal RobotAction? Next()
    {
        SkipSeparators();
        if (_pos >= _length)
        {
            return null;
        }
        int line = _line, column = Column;
        StatementLine = line;
        StatementColumn = column;
        StatementLineStart = _lineStart;
        int nameStart = _pos;
        ReadOnlySpan<char> text = _text.AsSpan(0, _length);
        int end = nameStart;
        while ((uint)end < (uint)text.Length && (char.IsAsciiLetterOrDigit(text[end]) || text[end] == '_'))
        {
            end++;
        }
        _pos = end;
        if (_pos == nameStart || !char.IsAsciiLetter(_text[nameStart]))
        {
            throw Error(line, column, $"expected an instruction such as MoveTo(400, 300, 500), but found '{Describe(_text[nameStart])}'.");
        }
        // Known names are looked up in place: the catalogue's own string is used, so no name is allocated per statement. A
        // toolpath repeats one instruction for long runs, or alternates two (Move, Rotate, Move, …): the last two names found
        // are compared first, before hashing for the table.
        ReadOnlySpan<char> found = _text.AsSpan(nameStart, _pos - nameStart);
        string name;
        InstructionCatalog.Overload[] overloads;
        if (found.Length == _lastName.Length && found.SequenceEqual(_lastName))
        {
            (name, overloads) = (_lastName, _lastOverloads);
        }
        else if (found.Length == _otherName.Length && found.SequenceEqual(_otherName))
        {
            (name, overloads) = (_otherName, _otherOverloads);
            (_otherName, _otherOverloads) = (_lastName, _lastOverloads);
            (_lastName, _lastOverloads) = (name, overloads);
        }
        else if (InstructionCatalog.TryFind(found, out name, out overloads))
        {
            (_otherName, _otherOverloads) = (_lastName, _lastOverloads);
            (_lastName, _lastOverloads) = (name, overloads);
        }
        else
        {
            name = new string(_text, nameStart, _pos - nameStart);
            overloads = Resolve(name, line, column);
        }
        SkipSpaces();
        if (_pos >= _length || _text[_pos] != '(')
        {
            throw Error(_line, Column, $"expected '(' after {name}.");
        }
        _pos++;
        _args.Begin(_text, name, line, column);
        ReadArguments(name);
        SkipSpaces();
        if (_pos < _length && _text[_pos] == ';')
        {
            _pos++;
        }
        return Create(overloads, line, column);
    }

    private InstructionCatalog.Overload[] Resolve(string name, int line, int column)
    {
        InstructionCatalog.Overload[]? overloads = InstructionCatalog.Find(name);
        if (overloads is not null)
        {
            return overloads;
        }
        string? proper = InstructionCatalog.ProperName(name);
        if (proper is not null)
        {
            throw Error(line, column, $"unknown instruction \"{name}\"; did you mean \"{proper}\"? Instruction names are case-sensitive.");
        }
        IReadOnlyList<string> close = InstructionSuggestion.For(name);
        throw Error(line, column, close.Count > 0
            ? $"unknown instruction \"{name}\"; did you mean {InstructionSuggestion.Quoted(close)}?"
            : $"unknown instruction \"{name}\".");
    }

    private RobotAction Create(InstructionCatalog.Overload[] overloads, int line, int column)
    {
        int count = _args.Count;
        foreach (InstructionCatalog.Overload overload in overloads)
        {
            if (count >= overload.MinArgs && count <= overload.MaxArgs)
            {
                try
                {
                    return overload.Create(_args);
                }
                catch (ArgumentException ex)
                {
                    throw Error(line, column, $"{_args.Name}: {FirstSentence(ex.Message)}");
                }
            }
        }
        string usages = string.Join(" or ", overloads.Select(o => o.Usage));
        throw Error(line, column, $"{_args.Name} was given {count} argument{(count == 1 ? "" : "s")}; use it as {usages}.");
    }

    private static string FirstSentence(string message)
    {
        int paren = message.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return paren > 0 ? message[..paren] : message;
    }

    private void ReadArguments(string name)
    {
        if (TryReadNumbers())
        {
            return;
        }
        SkipGaps();
        if (_pos < _length && _text[_pos] == ')')
        {
            _pos++;
            return;
        }
        while (true)
        {
            SkipGaps();
            if (_pos >= _length)
            {
                throw NotClosed(name);
            }
            ref InstructionArgs.Arg arg = ref _args.Next(_line, Column);
            if (_text[_pos] == '"')
            {
                ReadString(ref arg);
            }
            else if (!ReadPlainNumber(ref arg))
            {
                ReadBare(ref arg, name);
            }
            SkipGaps();
            if (_pos >= _length)
            {
                throw NotClosed(name);
            }
            char c = _text[_pos++];
            if (c == ')')
            {
                return;
            }
            if (c != ',')
            {
                throw Error(_line, Column - 1, $"expected ',' or ')' in {name}(...), but found '{Describe(c)}'.");
            }
        }
    }

    /// <summary>
    /// The arguments of a toolpath's statement (<c>12.5, -3, 0.25)</c>: plain numbers, each ending at ',' or ')', with spaces
    /// before them) read in one loop over local copies of the text and position, to the position after the ')'. Each is read
    /// as <see cref="ReadPlainNumber"/> reads it and given the line and column the general loop gives it. False for anything
    /// else (no argument, text, a comment, a line break, a space before a ','); the arguments read are then dropped and
    /// nothing is consumed, so the general loop reads the statement from the same place, to the same arguments or error.
    /// </summary>
    private bool TryReadNumbers()
    {
        ReadOnlySpan<char> text = _text.AsSpan(0, _length);
        int pos = _pos;
        int line = _line;
        int lineStart = _lineStart;
        while (true)
        {
            while ((uint)pos < (uint)text.Length && text[pos] == ' ')
            {
                pos++;
            }
            int end = NumParse.ReadShortAt(text, pos, out double value);
            if (end < 0 || end >= text.Length || (text[end] != ',' && text[end] != ')'))
            {
                _args.Drop();
                return false;
            }
            _args.AddNumber(line, pos - lineStart + 1, pos, end - pos, value);
            pos = end + 1;
            if (text[end] == ')')
            {
                _pos = pos;
                return true;
            }
        }
    }

    private void ReadString(ref InstructionArgs.Arg arg)
    {
        int start = ++_pos;
        while (_pos < _length)
        {
            char c = _text[_pos];
            if (c == '\\' && _pos + 1 < _length && _text[_pos + 1] != '\n')
            {
                _pos += 2;
                continue;
            }
            if (c == '"')
            {
                arg.Quoted = true;
                arg.Start = start;
                arg.Length = _pos - start;
                arg.Text = InstructionArgs.Unescape(_text.AsSpan(start, _pos - start));
                _pos++;
                return;
            }
            if (c == '\n')
            {
                break;
            }
            _pos++;
        }
        throw Error(arg.Line, arg.Column, "this text is not closed with a double quote (\"); write a quote inside text as \\\".");
    }

    /// <summary>
    /// Reads a plain number that ends its argument (<c>-12.5</c> right before ',' or ')', the form of nearly every argument
    /// of a toolpath) in one pass, its value as <see cref="NumParse.TryParseShort"/> reads the same characters; false, and
    /// nothing read, for anything else (which <see cref="ReadBare"/> reads, and <see cref="InstructionArgs.D"/> parses).
    /// </summary>
    private bool ReadPlainNumber(ref InstructionArgs.Arg arg)
    {
        int read = NumParse.ReadShort(_text.AsSpan(_pos, _length - _pos), out double value);
        int end = _pos + read;
        if (read <= 0 || end >= _length || (_text[end] != ',' && _text[end] != ')'))
        {
            return false;
        }
        arg.Start = _pos;
        arg.Length = read;
        arg.Number = value;
        arg.IsNumber = true;
        _pos = end;
        return true;
    }

    private void ReadBare(ref InstructionArgs.Arg arg, string name)
    {
        int start = _pos;
        while (_pos < _length)
        {
            char c = _text[_pos];
            if (c == ',' || c == ')' || c == '\n' || c == '(' || c == ';' || c == '"')
            {
                break;
            }
            if (c == '/' && IsCommentStart(_pos) && (_pos == start || char.IsWhiteSpace(_text[_pos - 1])))
            {
                // "1 // note" ends the value; "http://host" stays text.
                break;
            }
            _pos++;
        }
        int end = _pos;
        while (end > start && char.IsWhiteSpace(_text[end - 1]))
        {
            end--;
        }
        if (end == start)
        {
            throw Error(arg.Line, arg.Column, $"a value is missing in {name}(...).");
        }
        arg.Start = start;
        arg.Length = end - start;
    }

    private void SkipSpaces()
    {
        while (_pos < _length && (_text[_pos] == ' ' || _text[_pos] == '\t'))
        {
            _pos++;
        }
    }

    /// <summary>Skips white space, line breaks and <c>//</c> comments between the arguments of a statement.</summary>
    private void SkipGaps()
    {
        while (_pos < _length)
        {
            // The common cases first: one space between arguments, or a value or ')' at once (an ASCII character above the
            // space is no white space; only '/' may start a comment).
            char c = _text[_pos];
            if (c == ' ')
            {
                _pos++;
                continue;
            }
            if (c > ' ' && c < '\u0080' && c != '/')
            {
                return;
            }
            if (char.IsWhiteSpace(c))
            {
                Advance();
            }
            else if (IsCommentStart(_pos))
            {
                SkipComment();
            }
            else
            {
                return;
            }
        }
    }

    private bool IsCommentStart(int pos) => _text[pos] == '/' && pos + 1 < _length && _text[pos + 1] == '/';

    private void SkipComment()
    {
        while (_pos < _length && _text[_pos] != '\n')
        {
            _pos++;
        }
    }

    private void SkipSeparators()
    {
        while (_pos < _length)
        {
            char c = _text[_pos];
            // The common cases first: the line break after a statement, then a letter (no ASCII character above the space
            // but ';' and '/' is a separator or starts a comment).
            if (c == '\n')
            {
                _line++;
                _lineStart = ++_pos;
                continue;
            }
            if (c > ' ' && c < '\u0080' && c != ';' && c != '/')
            {
                return;
            }
            if (char.IsWhiteSpace(c) || c == ';' || c == '\uFEFF')
            {
                Advance();
            }
            else if (IsCommentStart(_pos))
            {
                SkipComment();
            }
            else
            {
                return;
            }
        }
    }

    private void Advance()
    {
        if (_text[_pos] == '\n')
        {
            _line++;
            _lineStart = _pos + 1;
        }
        _pos++;
    }

    /// <summary>The end of the text inside a statement: a parse error at the real end, else the statement continues in the next piece.</summary>
    private Exception NotClosed(string name) =>
        _final ? Error(_line, Column, $"{name}( is not closed with ')'.") : new StatementCutException();

    private static string Describe(char c) => char.IsControl(c) ? $"\\u{(int)c:x4}" : c.ToString();

    private static InstructionParseException Error(int line, int column, string problem) => new(line, column, problem);
}

/// <summary>Thrown by a parser of a piece that is not the last, when a statement runs past its end (see <see cref="InstructionReader"/>).</summary>
internal sealed class StatementCutException : Exception
{
}

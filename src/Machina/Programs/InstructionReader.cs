namespace Machina;

/// <summary>
/// Reads instruction text from a <see cref="TextReader"/> piece by piece, so that a file of any length is parsed in a small,
/// constant amount of memory. Each piece ends at a line break; a statement whose arguments run over several lines and past
/// the end of a piece is read again from the start of its line together with the next piece. Positions in errors are those of
/// the whole text.
/// </summary>
internal sealed class InstructionReader
{
    /// <summary>Characters read at a time (a piece is at least this long, unless the text ends first).</summary>
    internal const int PieceSize = 1 << 14;

    /// <summary>
    /// Longest line, and longest statement, read (16 Mi characters): a whole program may be written on one line, but a file
    /// with a longer one is not a program, and reading it whole would take gigabytes.
    /// </summary>
    internal const int MaxLineChars = 1 << 24;

    private readonly TextReader _reader;
    private readonly InstructionArgs _args = new();
    private char[] _buffer = new char[PieceSize * 2];
    private int _buffered;
    private bool _ended;
    private InstructionParser? _parser;

    internal InstructionReader(TextReader reader) => _reader = reader;

    /// <summary>Line (from 1) of the statement returned last.</summary>
    internal int Line { get; private set; }

    /// <summary>Column (from 1) of the statement returned last.</summary>
    internal int Column { get; private set; }

    /// <summary>The next action, or null at the end of the text.</summary>
    /// <exception cref="InstructionParseException">The text is malformed, or a value is not acceptable.</exception>
    internal RobotAction? Next()
    {
        while (true)
        {
            if (_parser is null)
            {
                if (!NextPiece(carry: null, firstLine: 1, start: 0))
                {
                    return null;
                }
            }
            InstructionParser parser = _parser!;
            RobotAction? action;
            try
            {
                action = parser.Next();
            }
            catch (StatementCutException)
            {
                // Read the statement again from the start of its line, with more text after it.
                string piece = parser.Text;
                NextPiece(piece.AsSpan(parser.StatementLineStart), parser.StatementLine, parser.StatementColumn - 1);
                continue;
            }
            if (action is not null)
            {
                Line = parser.StatementLine;
                Column = parser.StatementColumn;
                return action;
            }
            if (_ended)
            {
                return null;
            }
            NextPiece(carry: null, parser.Line, start: 0);
        }
    }

    /// <summary>
    /// Makes the parser for the next piece: <paramref name="carry"/> (the start of a cut statement's line) followed by text up
    /// to and including the last line break read. Returns false when there is no text left.
    /// </summary>
    private bool NextPiece(ReadOnlySpan<char> carry, int firstLine, int start)
    {
        if (carry.Length > MaxLineChars)
        {
            throw new InstructionParseException(firstLine, start + 1,
                $"this statement is longer than {MaxLineChars} characters, the most Machina reads as one statement (is a quote or a parenthesis left open?)");
        }
        // The buffer holds, from its start, text read but not yet given to a parser (the tail after the last line break).
        int needed = carry.Length + _buffered + PieceSize;
        if (needed > _buffer.Length)
        {
            Array.Resize(ref _buffer, Math.Max(needed, _buffer.Length * 2));
        }
        if (carry.Length > 0)
        {
            _buffer.AsSpan(0, _buffered).CopyTo(_buffer.AsSpan(carry.Length));
            carry.CopyTo(_buffer);
            _buffered += carry.Length;
        }
        int end = -1;
        while (!_ended)
        {
            if (_buffered == _buffer.Length)
            {
                Array.Resize(ref _buffer, _buffer.Length * 2);
            }
            int read = _reader.Read(_buffer, _buffered, _buffer.Length - _buffered);
            if (read == 0)
            {
                _ended = true;
                break;
            }
            int from = _buffered;
            _buffered += read;
            // A piece must end at a line break, and hold at least what was carried plus a full read.
            end = _buffer.AsSpan(0, _buffered).LastIndexOf('\n');
            if (_buffered - (end + 1) > MaxLineChars)
            {
                int line = firstLine + _buffer.AsSpan(0, end + 1).Count('\n');
                throw new InstructionParseException(line, 1,
                    $"this line is longer than {MaxLineChars} characters, the most Machina reads as one line; is the file a program?");
            }
            // (at least as much as was carried, so that a statement over many lines is read again only a few times).
            if (end >= carry.Length && end >= from && _buffered - carry.Length >= Math.Max(PieceSize, carry.Length))
            {
                break;
            }
        }
        int length = _ended ? _buffered : end + 1;
        if (length == 0 && _ended)
        {
            _parser = null;
            return false;
        }
        string text = new(_buffer, 0, length);
        _buffered -= length;
        _buffer.AsSpan(length, _buffered).CopyTo(_buffer);
        _parser = new InstructionParser(text, _args, firstLine, start, isFinal: _ended);
        return true;
    }
}

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
    private int _pieceLength;
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
                if (!NextPiece(carryFrom: 0, firstLine: 1, start: 0))
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
                NextPiece(parser.StatementLineStart, parser.StatementLine, parser.StatementColumn - 1);
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
            NextPiece(carryFrom: _pieceLength, parser.Line, start: 0);
        }
    }

    /// <summary>
    /// Makes the parser for the next piece: the text of the current piece from <paramref name="carryFrom"/> on (the start of a
    /// cut statement's line; the piece's length when nothing is carried), followed by text up to and including the last line
    /// break read. The parser reads the buffer in place, so no string is made per piece. Returns false when there is no text left.
    /// </summary>
    private bool NextPiece(int carryFrom, int firstLine, int start)
    {
        int carry = _pieceLength - carryFrom;
        if (carry > MaxLineChars)
        {
            throw new InstructionParseException(firstLine, start + 1,
                $"this statement is longer than {MaxLineChars} characters, the most Machina reads as one statement (is a quote or a parenthesis left open?)");
        }
        // The buffer holds, from its start, the piece given to the last parser, then the text read after it. What that parser
        // was done with goes; the carried line and the text after the piece (contiguous) move to the start.
        _buffer.AsSpan(carryFrom, _buffered - carryFrom).CopyTo(_buffer);
        _buffered -= carryFrom;
        _pieceLength = 0;
        int needed = _buffered + PieceSize;
        if (needed > _buffer.Length)
        {
            Array.Resize(ref _buffer, Math.Max(needed, _buffer.Length * 2));
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
            if (end >= carry && end >= from && _buffered - carry >= Math.Max(PieceSize, carry))
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
        _pieceLength = length;
        _parser = new InstructionParser(_buffer, length, _args, firstLine, start, isFinal: _ended);
        return true;
    }
}

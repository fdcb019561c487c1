using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RAPID driver's request parser (<c>ParseChunk</c> in drivers/abb/machina_abb_driver.mod), run alone on the RAPID twin: chunks
/// as <c>SocketReceive</c> hands them over (a request split anywhere), then what the driver buffered, wrote on the pendant and
/// whether it stopped. The expected values are what the driver of 1.7.0 that read one character at a time gave; the driver that
/// reads a run of characters at a time (StrFind), and requests of numbers whole (ReadWhole, JoinPending), must give the same for
/// every edge (issue 45).
/// </summary>
public class RapidDriverParserTests
{
    private const string End = "end";

    /// <summary>Parses <paramref name="chunks"/> in order, then writes each buffered request and the parser's state on the pendant.</summary>
    private static List<string> Parse(bool strict, params string[] chunks)
    {
        var probe = new StringBuilder("MODULE ParserProbe\nPROC Probe()\n");
        probe.Append("USE_STRICT := ").Append(strict ? "TRUE" : "FALSE").Append(";\n");
        foreach (string chunk in chunks)
        {
            // A chunk starting with '!' is a statement of the probe instead (ResetParser: a new client).
            probe.Append(chunk.StartsWith('!') ? chunk[1..] : "ParseChunk " + Literal(chunk)).Append(";\n");
        }
        probe.Append("""
            Show;
            ENDPROC
            PROC Show()
            VAR num k;
            VAR num n := 0;
            k := readIndex;
            WHILE n < requestCount DO
            TPWrite ValToStr(requests{k}.id) + " " + ValToStr(requests{k}.code) + " " + ValToStr(requests{k}.p1) + " " + ValToStr(requests{k}.p2) + " " + ValToStr(requests{k}.p3) + " " + ValToStr(requests{k}.p4) + " " + ValToStr(requests{k}.p5);
            TPWrite ValToStr(requests{k}.p6) + " " + ValToStr(requests{k}.p7) + " " + ValToStr(requests{k}.p8) + " " + ValToStr(requests{k}.p9) + " " + ValToStr(requests{k}.p10) + " " + ValToStr(requests{k}.p11);
            TPWrite "[" + requests{k}.s1 + "]";
            k := k MOD BUFFER_SIZE + 1;
            n := n + 1;
            ENDWHILE
            TPWrite "field " + ValToStr(field) + " text " + ValToStr(inText) + " corrupt " + ValToStr(corrupt) + " received " + ValToStr(lastReceivedId);
            TPWrite "token [" + token + "]";
            TPWrite "end";
            ENDPROC
            ENDMODULE
            """);
        var twin = new RapidTwinController();
        twin.Load(("machina_abb_driver.mod", AbbDriverModules.Create("127.0.0.1", 1000)["machina_abb_driver.mod"]), ("ParserProbe.mod", probe.ToString()));
        Assert.Equal(RapidProgramState.Finished, twin.Run("Probe"));
        Assert.Null(twin.Error);
        return [.. twin.Pendant.Lines];
    }

    /// <summary><paramref name="text"/> as a RAPID string literal (quotes doubled, backslashes and control characters escaped).</summary>
    private static string Literal(string text)
    {
        var literal = new StringBuilder("\"");
        foreach (char c in text)
        {
            literal.Append(c switch
            {
                '"' => "\"\"",
                '\\' => "\\\\",
                < ' ' => $"\\{(int)c:X2}",
                _ => c.ToString(),
            });
        }
        return literal.Append('"').ToString();
    }

    private static string[] State(int field = 0, bool inText = false, bool corrupt = false, int received = 0, string token = "") =>
        [$"field {field} text {(inText ? "TRUE" : "FALSE")} corrupt {(corrupt ? "TRUE" : "FALSE")} received {received}", $"token [{token}]", End];

    [Fact]
    public void Requests_OnePerChunkOrManyInOne_AreBufferedWithEveryNumber_MissingOnesZero()
    {
        List<string> lines = Parse(true, "@12 1 400 0 500 0 0 1 0;", "@13 4 100;@14 8 0 -0.5 100 1 0 0 0 1.5 2 3 50;@0 31 0 0 1 0;");

        Assert.Equal(
        [
            "12 1 400 0 500 0 0", "1 0 0 0 0 0", "[]",
            "13 4 100 0 0 0 0", "0 0 0 0 0 0", "[]",
            "14 8 0 -0.5 100 1 0", "0 0 1.5 2 3 50", "[]",
            "0 31 0 0 1 0 0", "0 0 0 0 0 0", "[]",
            .. State(received: 14),
        ], lines);
    }

    [Fact]
    public void ARequestSplitAtAnyCharacter_ReadsAsInOneChunk()
    {
        const string Stream = "@21 8 0 -0.5 100 1 0 0 0 1.5 2 3 50;@22 7 \"a b;c\" 9;";
        string[] expected = ["21 8 0 -0.5 100 1 0", "0 0 1.5 2 3 50", "[]", "22 7 9 0 0 0 0", "0 0 0 0 0 0", "[a b;c]"];
        var chunks = new List<string>();
        for (int k = 1; k < Stream.Length; k++)
        {
            chunks.Add(Stream[..k]);
            chunks.Add(Stream[k..]);
        }
        chunks.AddRange(Stream.Select(c => c.ToString())); // one character per chunk

        List<string> lines = Parse(true, [.. chunks]);

        Assert.Equal([.. Enumerable.Repeat(expected, Stream.Length).SelectMany(e => e), .. State(received: 22)], lines);
    }

    [Fact]
    public void QuotedText_KeepsSpacesSemicolonsAndAtSigns_TextAndNumbersKeepTheirFirst80Characters()
    {
        string a = new('a', 40), b = new('b', 50), ones = new('1', 45);

        List<string> lines = Parse(true, "@5 7 \"Hello;  world @ 1\";@6 7 \"" + a, b + "\" 3;", "@7 4 " + ones, ones + ";@8 7 \"\";@9 7 \"", "x\";");

        Assert.Equal(
        [
            "5 7 0 0 0 0 0", "0 0 0 0 0 0", "[Hello;  world @ 1]",
            "6 7 3 0 0 0 0", "0 0 0 0 0 0", $"[{a}{b[..40]}]",
            "7 4 1.11111E79 0 0 0 0", "0 0 0 0 0 0", "[]",
            "8 7 0 0 0 0 0", "0 0 0 0 0 0", "[]",
            "9 7 0 0 0 0 0", "0 0 0 0 0 0", "[x]",
            .. State(received: 9),
        ], lines);
    }

    [Fact]
    public void TextAnywhere_SecondTextWins_UnclosedTextWaitsForItsQuote()
    {
        List<string> lines = Parse(true, "@10 7\"x y\"3;@11 7 \"a\" \"b\";@12 10 \"DO_1\"", "1;@13 7 \"open; still", " text");

        Assert.Equal(
        [
            "10 7 3 0 0 0 0", "0 0 0 0 0 0", "[x y]",
            "11 7 0 0 0 0 0", "0 0 0 0 0 0", "[b]",
            "12 10 1 0 0 0 0", "0 0 0 0 0 0", "[DO_1]",
            .. State(field: 1, inText: true, received: 12, token: "open; still text"),
        ], lines);
    }

    [Fact]
    public void Whitespace_TabsAndLineEnds_SeparateTokens_EmptyRequestsAndIdAloneAreDroppedQuietly()
    {
        List<string> lines = Parse(true, "@9\t4\r\n10  ;;  ;@11;\n", "4 20;@12 \t 5\n0 ;  @13 4 1");

        Assert.Equal(
        [
            "9 4 10 0 0 0 0", "0 0 0 0 0 0", "[]",
            "0 4 20 0 0 0 0", "0 0 0 0 0 0", "[]",
            "12 5 0 0 0 0 0", "0 0 0 0 0 0", "[]",
            .. State(field: 1, received: 12, token: "1"),
        ], lines);
    }

    [Fact]
    public void AtSign_StartsTheIdOnlyBeforeAnything_ElsewhereItIsPartOfAToken_NotStrict()
    {
        List<string> lines = Parse(false, "@@5 4 1;@6 4 2;5@6 4 1;@7 4 1@;@8 4 3;");

        Assert.Equal(
        [
            "@5", "Machina: received corrupt value", "Machina: received corrupt request",
            "5@6", "Machina: received corrupt value", "Machina: received corrupt request",
            "1@", "Machina: received corrupt value", "Machina: received corrupt request",
            "6 4 2 0 0 0 0", "0 0 0 0 0 0", "[]",
            "8 4 3 0 0 0 0", "0 0 0 0 0 0", "[]",
            .. State(received: 8),
        ], lines);
    }

    [Fact]
    public void CorruptValueOrTwelfthNumber_NotStrict_DropsThatRequestAndReadsOn()
    {
        List<string> lines = Parse(false, "@7 4 abc;@8 17 1 2 3 4 5 6 7 8 9 10 11 12;@9 17 1 2 3 4 5 6 7 8 9 10 11;@10 4 1x", "2;@11 4 5;");

        Assert.Equal(
        [
            "abc", "Machina: received corrupt value", "Machina: received corrupt request",
            "Machina: more than 11 parameters", "Machina: received corrupt request",
            "1x2", "Machina: received corrupt value", "Machina: received corrupt request",
            "9 17 1 2 3 4 5", "6 7 8 9 10 11", "[]",
            "11 4 5 0 0 0 0", "0 0 0 0 0 0", "[]",
            .. State(received: 11),
        ], lines);
    }

    [Theory]
    [InlineData("@7 4 1;@8 4 abc;@9 4 1;", "abc", "Machina: received corrupt value")]
    [InlineData("@8 17 1 2 3 4 5 6 7 8 9 10 11 12;", null, "Machina: more than 11 parameters")]
    [InlineData("@8 4 1 \"never closed", null, null)]
    public void Strict_TheFirstProblemStopsTheProgram(string chunk, string? token, string? complaint)
    {
        List<string> lines = Parse(true, chunk);

        if (complaint is null)
        {
            Assert.Equal(["field 2 text TRUE corrupt FALSE received 0", "token [never closed]", End], lines);
            return;
        }
        Assert.Equal([.. token is null ? [] : new[] { token }, complaint], lines);
    }

    [Fact]
    public void RequestsOfNumbers_ReadWhole_EdgesReadAsByTheTokenParser_NotStrict()
    {
        // Single spaces (one before the ';' too): read whole. A double or leading space, an id alone, a corrupt number, "@;", a 12th
        // number: the token parser from the same '@' (what it always did: spaces skipped, the rest refused with its complaint).
        List<string> lines = Parse(false, "@1 4 100;@2 5  3;@ 3 4 7;@4 4 8 ;@5;@;@6 17 1 2 3 4 5 6 7 8 9 10 11;", "@7 17 1 2 3 4 5 6 7 8 9 10 11 12;@8 4 1.2.3;@9 4 -1.5E2;@10 4 +2;");

        Assert.Equal(
        [
            "Machina: received corrupt request",
            "Machina: more than 11 parameters", "Machina: received corrupt request",
            "1.2.3", "Machina: received corrupt value", "Machina: received corrupt request",
            "1 4 100 0 0 0 0", "0 0 0 0 0 0", "[]",
            "2 5 3 0 0 0 0", "0 0 0 0 0 0", "[]",
            "3 4 7 0 0 0 0", "0 0 0 0 0 0", "[]",
            "4 4 8 0 0 0 0", "0 0 0 0 0 0", "[]",
            "6 17 1 2 3 4 5", "6 7 8 9 10 11", "[]",
            "9 4 -150 0 0 0 0", "0 0 0 0 0 0", "[]",
            "10 4 2 0 0 0 0", "0 0 0 0 0 0", "[]",
            .. State(received: 10),
        ], lines);
    }

    [Fact]
    public void AStreamOfMoves_CutIntoChunksOfAnySize_ReadsTheSame()
    {
        var stream = new StringBuilder();
        var expected = new List<string>();
        for (int id = 1; id <= 12; id++)
        {
            string x = (374 + id % 2 + id / 10.0).ToString(System.Globalization.CultureInfo.InvariantCulture);
            stream.Append('@').Append(id).Append(" 1 ").Append(x).Append(" -0.5 630 0.7071 0 0.7071 0;");
            expected.AddRange([$"{id} 1 {x} -0.5 630 0.7071 0", "0.7071 0 0 0 0 0", "[]"]);
        }
        string text = stream.ToString();
        foreach (int size in new[] { 1, 7, 29, 36, 37, 41, 64, 79, 80 })
        {
            List<string> chunks = [.. Enumerable.Range(0, (text.Length + size - 1) / size).Select(k => text.Substring(k * size, Math.Min(size, text.Length - k * size)))];

            List<string> lines = Parse(true, [.. chunks]);

            Assert.Equal([.. expected, .. State(received: 12)], lines);
        }
    }

    [Fact]
    public void ARequestsStartThatAChunkEndedIn_IsForgottenWithTheParser_AsWhenTheTokenParserHeldIt()
    {
        // ResetParser is what a new client gets (AcceptClient): the old client's unfinished request is not joined to the new stream.
        List<string> lines = Parse(true, "@1 4 10;@2 4 2", "!ResetParser", "@3 4 30;", "@4 4", " 40;");

        Assert.Equal(
        [
            "1 4 10 0 0 0 0", "0 0 0 0 0 0", "[]",
            "3 4 30 0 0 0 0", "0 0 0 0 0 0", "[]",
            "4 4 40 0 0 0 0", "0 0 0 0 0 0", "[]",
            .. State(received: 4),
        ], lines);
    }

    [Fact]
    public void ACorruptNumberInARequestsStart_IsReportedWhenTheRequestEnds_Strict()
    {
        // A request of number characters that a chunk ends in waits whole for its end (the token parser reported "1.2.3" at its space);
        // the driver waits for the rest of the request either way, and the host never sends such a number (AbbStatementGrammar).
        Assert.Equal(State(), Parse(true, "@7 4 1.2.3 5"));
        Assert.Equal(["1.2.3", "Machina: received corrupt value"], Parse(true, "@7 4 1.2.3 5", "6;"));
    }
}

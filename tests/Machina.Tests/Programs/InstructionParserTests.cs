namespace Machina.Tests.Programs;

/// <summary>The instruction language: statements, comments, strings, optional arguments and precise errors.</summary>
public class InstructionParserTests
{
    private static InstructionParseException ParseError(string text) => Assert.Throws<InstructionParseException>(() => Instructions.Parse(text));

    [Fact]
    public void Parse_SeveralStatementsOnOneLine_ReturnsThemInOrder()
    {
        var actions = Instructions.Parse("SpeedTo(100); MoveTo(400,300,500);Wait(2000);");

        Assert.Equal<RobotAction>(
            [new ActionSpeed(100, false), new ActionTranslation(new Vector(400, 300, 500), false), new ActionWait(2000)],
            actions);
    }

    [Fact]
    public void Parse_NumbersRightBeforeCommaOrParenthesis_SameValuesAsTheGeneralParser()
    {
        // Plain numbers that end their argument are read in one pass with the statement; every other form (spaces, a
        // comment, exponents, 16 digits, two points) still goes through the general reading. Both give double.Parse's value.
        string[] forms = ["0", "-0", "+1.5", "1.", ".5", "-.25", "007", "123456789012345", "1234567890123456", "0.000000000000001",
                          "1e3", "-2.5E-3", " 4.5", "4.5 ", "4.5 // note\n", "9999999999.99999", "12.125", "-300"];
        var random = new Random(27);
        var texts = new List<string>(forms);
        for (int i = 0; i < 3_000; i++)
        {
            texts.Add(Math.Round((random.NextDouble() - 0.5) * Math.Pow(10, random.Next(0, 12)), random.Next(0, 9)).ToString("R", System.Globalization.CultureInfo.InvariantCulture));
        }
        foreach (string text in texts)
        {
            var move = Assert.IsType<ActionTranslation>(Assert.Single(Instructions.Parse($"Move({text},{text},{text});")));
            double expected = double.Parse(text.Split("//")[0], System.Globalization.NumberStyles.Float, System.Globalization.CultureInfo.InvariantCulture);
            Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(move.Translation.X));
            Assert.Equal(BitConverter.DoubleToInt64Bits(expected), BitConverter.DoubleToInt64Bits(move.Translation.Z));
        }
        Assert.Throws<InstructionParseException>(() => Instructions.Parse("Move(1.2.3,0,0);"));
        Assert.Throws<InstructionParseException>(() => Instructions.Parse("Move(-,0,0);"));
    }

    [Theory]
    [InlineData("Rotate(0, 0, 1, 1e400)", 1, 17, "argument 4 of Rotate")]
    [InlineData("Move(1, 2,x)", 1, 11, "argument 3 of Move")]
    [InlineData("\n  Rotate(1,2, 3 , abc)", 2, 19, "argument 4 of Rotate")]
    [InlineData("Move(1, 2,\n  x)", 2, 3, "argument 3 of Move")]
    [InlineData("MoveTo(1, 2, 3", 1, 15, "MoveTo( is not closed")]
    public void Parse_PlainNumbersThenAnotherForm_ErrorAtTheArgumentAsBefore(string text, int line, int column, string problem)
    {
        // A statement's plain numbers are read in one loop; at the first other form the statement is read again the general
        // way, which must point at the same argument as if the loop did not exist.
        var ex = ParseError(text);

        Assert.Equal((line, column), (ex.Line, ex.Column));
        Assert.StartsWith(problem, ex.Problem, StringComparison.Ordinal);
    }

    [Fact]
    public void Parse_PlainNumbersThenAnotherForm_ReadAsTheGeneralParserReadsThem()
    {
        var actions = Instructions.Parse("Move(1, 2, 3 // up\n);MoveTo(1, 2,\n 3)\nRotate(0, 0, 1, \"45\");Move(1 , 2);Move(\t4, 5)");

        Assert.Equal<RobotAction>(
            [new ActionTranslation(new Vector(1, 2, 3), true), new ActionTranslation(new Vector(1, 2, 3), false),
             new ActionRotation(new Vector(0, 0, 1), 45, true), new ActionTranslation(new Vector(1, 2, 0), true),
             new ActionTranslation(new Vector(4, 5, 0), true)],
            actions);
    }

    [Fact]
    public void Parse_CommentsOnTheirOwnLineAndAfterStatements_AreIgnored()
    {
        var actions = Instructions.Parse("// header\nMove(1, 2, 3); // up a bit\n  // indented comment\nWait(5) // no semicolon\n//");

        Assert.Equal<RobotAction>([new ActionTranslation(new Vector(1, 2, 3), true), new ActionWait(5)], actions);
    }

    [Fact]
    public void Parse_DoubleSlashInsideString_IsText()
    {
        var action = (ActionMessage)Assert.Single(Instructions.Parse("Message(\"see http://x.org // here\"); // real comment"));

        Assert.Equal("see http://x.org // here", action.Message);
    }

    [Fact]
    public void Parse_MissingFinalSemicolon_IsAccepted()
    {
        Assert.Equal<RobotAction>([new ActionDetachTool()], Instructions.Parse("DetachTool()"));
    }

    [Fact]
    public void Parse_TabsCrLfAndSpaces_AreWhitespace()
    {
        var actions = Instructions.Parse("\tMoveTo (\t1 ,\r\n 2,\t3 ) ;\r\n\r\n  Speed( -5 )\t;\r\n");

        Assert.Equal<RobotAction>([new ActionTranslation(new Vector(1, 2, 3), false), new ActionSpeed(-5, true)], actions);
    }

    [Fact]
    public void Parse_ByteOrderMarkAndEmptyText_GiveNoProblem()
    {
        Assert.Empty(Instructions.Parse(""));
        Assert.Empty(Instructions.Parse(" ;; \n// only a comment"));
        Assert.Single(Instructions.Parse("\uFEFFWait(1);"));
    }

    [Fact]
    public void Parse_UnquotedString_IsTakenAsText()
    {
        var message = (ActionMessage)Assert.Single(Instructions.Parse("Message(Hello world);"));
        var tool = (ActionAttachTool)Assert.Single(Instructions.Parse("AttachTool( pen )"));

        Assert.Equal("Hello world", message.Message);
        Assert.Equal("pen", tool.ToolName);
    }

    [Fact]
    public void Parse_EscapesInStrings_AreResolved()
    {
        var message = (ActionMessage)Assert.Single(Instructions.Parse(@"Message(""a\""b\\c\nd\te\u00e9\q"");"));

        Assert.Equal("a\"b\\c\nd\te\u00e9\\q", message.Message);
    }

    [Fact]
    public void Parse_ParenthesesAndCommasInsideStrings_AreText()
    {
        var message = (ActionMessage)Assert.Single(Instructions.Parse("Message(\"a(b)c, d;\")"));

        Assert.Equal("a(b)c, d;", message.Message);
    }

    [Theory]
    [InlineData("true", true)]
    [InlineData("TRUE", true)]
    [InlineData("True", true)]
    [InlineData("fAlSe", false)]
    [InlineData("\"false\"", false)]
    public void Parse_BooleansInAnyCase_AreRead(string text, bool expected)
    {
        var action = (ActionIODigital)Assert.Single(Instructions.Parse($"WriteDigital(1, {text});"));

        Assert.Equal(expected, action.On);
    }

    [Fact]
    public void Parse_OptionalArguments_TakeTheirDefaults()
    {
        var actions = Instructions.Parse("Move(1,2); Extrude(); Message(); WriteAnalog(\"AO\", 2); TemperatureTo(200, bed); ExternalAxis(2, 5); CustomCode(\"x\")");

        Assert.Equal<RobotAction>(
            [
                new ActionTranslation(new Vector(1, 2, 0), true), new ActionExtrusion(true), new ActionMessage(""),
                new ActionIOAnalog("AO", 2, false), new ActionTemperature(200, RobotPartType.Bed, true, false),
                new ActionExternalAxis(2, 5, ExternalAxesTarget.All, true), new ActionCustomCode("x", false),
            ],
            actions);
    }

    [Fact]
    public void Parse_EnumArgumentsInAnyCase_AreRead()
    {
        var actions = Instructions.Parse("MotionMode(\"joint\"); Coordinates(LOCAL); ExternalAxisTo(1, 2, \"cartesian\")");

        Assert.Equal<RobotAction>(
            [new ActionMotionMode(MotionType.Joint), new ActionCoordinates(ReferenceCS.Local), new ActionExternalAxis(1, 2, ExternalAxesTarget.Cartesian, false)],
            actions);
    }

    [Fact]
    public void Parse_ExponentNumbers_AreRead()
    {
        var action = (ActionTranslation)Assert.Single(Instructions.Parse("MoveTo(1e2, -2.5E-1, +3)"));

        Assert.Equal(new Vector(100, -0.25, 3), action.Translation);
    }

    [Fact]
    public void Parse_WrongCaseName_SuggestsTheProperName()
    {
        var ex = ParseError("Wait(1);\n  moveto(1,2,3);");

        Assert.Equal(2, ex.Line);
        Assert.Equal(3, ex.Column);
        Assert.Equal("unknown instruction \"moveto\"; did you mean \"MoveTo\"? Instruction names are case-sensitive.", ex.Problem);
        Assert.Equal("Line 2, column 3: " + ex.Problem, ex.Message);
    }

    [Fact]
    public void Parse_UnknownName_SaysSo()
    {
        var ex = ParseError("Fly(1)");

        Assert.Equal((1, 1), (ex.Line, ex.Column));
        Assert.Equal("unknown instruction \"Fly\".", ex.Problem);
    }

    [Fact]
    public void Parse_WrongArity_ListsTheUsage()
    {
        var ex = ParseError("MoveTo(1,2)");

        Assert.Equal((1, 1), (ex.Line, ex.Column));
        Assert.Equal("MoveTo was given 2 arguments; use it as MoveTo(x, y, z).", ex.Problem);
    }

    [Fact]
    public void Parse_WrongArityForOverloadedName_ListsEveryUsage()
    {
        var ex = ParseError("ArcMotionTo(1,2,3)");

        Assert.Equal(
            "ArcMotionTo was given 3 arguments; use it as ArcMotionTo(throughX, throughY, throughZ, endX, endY, endZ) or ArcMotionTo(through origin, X axis, Y axis, end origin, X axis, Y axis: 18 numbers).",
            ex.Problem);
    }

    [Fact]
    public void Parse_FractionalWait_IsRefusedAtTheArgument()
    {
        var ex = ParseError("Wait(1.5);");

        Assert.Equal((1, 6), (ex.Line, ex.Column));
        Assert.Equal("argument 1 of Wait must be a whole number (like 2000), but it is \"1.5\".", ex.Problem);
    }

    [Fact]
    public void Parse_TextWhereNumberExpected_PointsAtTheArgument()
    {
        var ex = ParseError("MoveTo(1, abc, 3)");

        Assert.Equal((1, 11), (ex.Line, ex.Column));
        Assert.Equal("argument 2 of MoveTo must be a number (like 12.5), but it is \"abc\".", ex.Problem);
    }

    [Theory]
    [InlineData("MoveTo(NaN,0,0)")]
    [InlineData("MoveTo(Infinity,0,0)")]
    [InlineData("MoveTo(1e400,0,0)")]
    [InlineData("MoveTo(1,5;0,0)")]
    public void Parse_NonFiniteOrMalformedNumbers_AreRefused(string text)
    {
        ParseError(text);
    }

    [Fact]
    public void Parse_BadBoolean_IsRefused()
    {
        var ex = ParseError("WriteDigital(1, 1)");

        Assert.Equal((1, 17), (ex.Line, ex.Column));
        Assert.Equal("argument 2 of WriteDigital must be true or false, but it is \"1\".", ex.Problem);
    }

    [Fact]
    public void Parse_UnclosedString_PointsAtTheOpeningQuote()
    {
        var ex = ParseError("Wait(1);\nMessage(\"abc);\nWait(2);");

        Assert.Equal((2, 9), (ex.Line, ex.Column));
        Assert.Equal("this text is not closed with a double quote (\"); write a quote inside text as \\\".", ex.Problem);
    }

    [Fact]
    public void Parse_UnclosedParenthesisAtEnd_PointsAtTheEnd()
    {
        var ex = ParseError("Wait(1);\nMoveTo(1,2,3");

        Assert.Equal((2, 13), (ex.Line, ex.Column));
        Assert.Equal("MoveTo( is not closed with ')'.", ex.Problem);
    }

    [Fact]
    public void Parse_UnclosedParenthesisBeforeSemicolon_PointsAtTheSemicolon()
    {
        var ex = ParseError("MoveTo(1,2,3;");

        Assert.Equal((1, 13), (ex.Line, ex.Column));
        Assert.Equal("expected ',' or ')' in MoveTo(...), but found ';'.", ex.Problem);
    }

    [Fact]
    public void Parse_MissingParenthesis_IsReported()
    {
        var ex = ParseError("PushSettings;");

        Assert.Equal((1, 13), (ex.Line, ex.Column));
        Assert.Equal("expected '(' after PushSettings.", ex.Problem);
    }

    [Fact]
    public void Parse_EmptyArgument_IsReported()
    {
        var ex = ParseError("Move(1,,2)");

        Assert.Equal((1, 8), (ex.Line, ex.Column));
        Assert.Equal("a value is missing in Move(...).", ex.Problem);
    }

    [Fact]
    public void Parse_StatementStartingWithSymbol_IsReported()
    {
        var ex = ParseError("Wait(1); 3Move(1,2)");

        Assert.Equal((1, 10), (ex.Line, ex.Column));
        Assert.Equal("expected an instruction such as MoveTo(400, 300, 500), but found '3'.", ex.Problem);
    }

    [Fact]
    public void Parse_ActionRefusingItsValues_ReportsTheStatement()
    {
        var ex = ParseError("Wait(1);\n SpeedTo(-5);");

        Assert.Equal((2, 2), (ex.Line, ex.Column));
        Assert.Equal("SpeedTo: Speed must be greater than 0 mm/s, but it was -5.", ex.Problem);
    }

    [Fact]
    public void Parse_UnknownEnumText_ListsTheChoices()
    {
        var ex = ParseError("MotionMode(\"circular\")");

        Assert.Equal((1, 12), (ex.Line, ex.Column));
        Assert.Equal("\"circular\" is not a valid motion type; use one of: Linear, Joint.", ex.Problem);
    }

    [Fact]
    public void Enumerate_LongProgram_ReadsLazilyUntilTheProblem()
    {
        var read = new List<RobotAction>();
        var ex = Assert.Throws<InstructionParseException>(() =>
        {
            foreach (RobotAction a in Instructions.Enumerate("Wait(1);\nWait(2);\nWait(x);"))
            {
                read.Add(a);
            }
        });

        Assert.Equal(2, read.Count);
        Assert.Equal(3, ex.Line);
    }

    [Fact]
    public void ParseFile_Utf8WithBom_ReadsAllStatements()
    {
        string path = Path.Combine(Path.GetTempPath(), $"machina-{Guid.NewGuid():N}.machina");
        try
        {
            File.WriteAllText(path, "Message(\"Grüße\");\r\nWait(3);\r\n", new System.Text.UTF8Encoding(true));

            var actions = Instructions.ParseFile(path);

            Assert.Equal<RobotAction>([new ActionMessage("Grüße"), new ActionWait(3)], actions);
        }
        finally
        {
            File.Delete(path);
        }
    }
}

public class InstructionParserCompatibilityTests
{
    [Fact]
    public void Parse_QuotedNumbers_AreReadAsTheOriginalDid()
    {
        var actions = Instructions.Parse("MoveTo(\"1\", 2, \"3.5\"); Wait(\"20\")");

        Assert.Equal<RobotAction>([new ActionTranslation(new Vector(1, 2, 3.5), false), new ActionWait(20)], actions);
    }

    [Fact]
    public void Parse_BackslashBeforeLineBreakInString_IsAnUnclosedString()
    {
        var ex = Assert.Throws<InstructionParseException>(() => Instructions.Parse("Message(\"abc\\\nWait(1);"));

        Assert.Equal((1, 9), (ex.Line, ex.Column));
    }

    [Fact]
    public void Parse_StatementsWithoutSeparator_AreBothRead()
    {
        Assert.Equal<RobotAction>([new ActionPushPop(true), new ActionPushPop(false)], Instructions.Parse("PushSettings()PopSettings()"));
    }
}

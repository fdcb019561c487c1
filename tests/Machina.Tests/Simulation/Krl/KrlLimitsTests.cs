using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The KRL twin's budgets (issue 40): each program here ended the process before (a stack overflow with no call-depth limit, an
/// unhandled exception or gigabytes for an array, a FOR loop that wrapped round; checked with <c>machina verify</c> on the build
/// before the budgets), and is now the program's error, with its file and line.
/// </summary>
public class KrlLimitsTests
{
    private static KrlLoadException Refused(string source, TwinLimits? limits = null) =>
        Assert.Throws<KrlLoadException>(() => new KrlTwinController(new KrlTwinOptions { Limits = limits ?? TwinLimits.Default }).Load(("prog.src", source)));

    private static string Failed(string source, TwinLimits? limits = null)
    {
        using var twin = new KrlTwinController(new KrlTwinOptions { Limits = limits ?? TwinLimits.Default });
        twin.Load(("prog.src", source));
        Assert.Equal(KrlProgramState.Failed, twin.Run());
        return twin.Error!;
    }

    private static string Repeat(string text, int count) => string.Concat(Enumerable.Repeat(text, count));

    [Fact]
    public void EndlessRecursion_StopsAtTheCallDepth()
    {
        string error = Failed("DEF prog( )\n  r( )\nEND\nDEF r( )\n  r( )\nEND\n");

        Assert.Equal("the subprogram calls are nested deeper than 200 levels (r) (prog.src, line 5)", error);
    }

    [Theory]
    [InlineData("DECL INT a[46341,46341]", "a: the array {46341,46341} has more than 1,000,000 elements (the twin's limit)")]
    [InlineData("DECL INT a[100000,100000,10]", "a: the array {100000,100000,10} has more than 1,000,000 elements (the twin's limit)")]
    [InlineData("CHAR s[2000000000]", "s: the array {2000000000} has more than 1,000,000 elements (the twin's limit)")]
    public void AnArrayPastTheElementLimit_IsRefusedAtLoad(string declaration, string reason)
    {
        KrlLoadException ex = Refused($"DEF prog( )\n  {declaration}\nEND\n");

        Assert.Equal(2, ex.Line);
        Assert.Equal(reason, ex.Reason);
    }

    [Fact]
    public void DataPastTheTotal_IsRefusedAtLoad()
    {
        string declarations = string.Concat(Enumerable.Range(1, 5).Select(i => $"  DECL INT a{i}[1000000]\n"));

        KrlLoadException ex = Refused($"DEF prog( )\n{declarations}END\n");

        Assert.Equal(6, ex.Line);
        Assert.Equal("the file's data hold more than 4,000,000 array elements (the twin's limit)", ex.Reason);
    }

    [Fact]
    public void RecursionWithLocalArrays_StopsAtTheTotal()
    {
        string error = Failed("DEF prog( )\n  r( )\nEND\nDEF r( )\n  DECL INT a[100000]\n  r( )\nEND\n");

        Assert.Equal("the subprograms' local data hold more than 4,000,000 array elements (the twin's limit) (prog.src, line 6)", error);
    }

    [Fact]
    public void TenThousandBrackets_AreRefusedAtLoad()
    {
        KrlLoadException ex = Refused($"DEF prog( )\n  DECL INT i\n  i = {Repeat("(", 10_000)}1{Repeat(")", 10_000)}\nEND\n");

        Assert.Equal(3, ex.Line);
        Assert.Equal("the file is nested more than 100 levels deep (brackets, signs and blocks)", ex.Reason);
    }

    [Fact]
    public void ASumOf200000Terms_IsRefusedAtLoad()
    {
        KrlLoadException ex = Refused($"DEF prog( )\n  DECL INT i\n  i = 1{Repeat("+1", 199_999)}\nEND\n");

        Assert.Equal(3, ex.Line);
        Assert.Equal("the expression has more than 2000 operators and calls", ex.Reason);
    }

    [Fact]
    public void FiftyThousandMinuses_AreRefusedAtLoad()
    {
        KrlLoadException ex = Refused($"DEF prog( )\n  DECL INT i\n  i = {Repeat("-", 50_000)}1\nEND\n");

        Assert.Equal("the file is nested more than 100 levels deep (brackets, signs and blocks)", ex.Reason);
    }

    [Fact]
    public void RecursionThroughDeepExpressions_OnASmallStack_IsTheProgramsStackOverflow()
    {
        string nested = Repeat("0 + (", 95) + "f(n + 1)" + Repeat(")", 95);
        string source = $"DEF prog( )\n  DECL INT i\n  i = f(0)\nEND\nDEFFCT INT f(n:IN)\n  DECL INT n\n  IF n > 150 THEN\n    RETURN 0\n  ENDIF\n  RETURN {nested}\nENDFCT\n";
        string? error = null;
        var thread = new Thread(() => error = Failed(source), 512 * 1024);
        thread.Start();
        Assert.True(thread.Join(TimeSpan.FromMinutes(2)));

        Assert.Equal("stack overflow: the subprogram calls and expressions are nested too deeply (prog.src, line 10)", error);
    }

    [Theory]
    [InlineData("  WHILE TRUE\n  ENDWHILE\n")]
    [InlineData("  LOOP\n  ENDLOOP\n")]
    [InlineData("  FOR i = 1 TO 2147483647\n  ENDFOR\n")]
    public void AnEndlessLoop_InAVerification_StopsAtTheStepBudget(string body)
    {
        var options = new KrlTwinOptions { Limits = TwinLimits.Verify with { MaxSteps = 100_000 } };

        TwinVerification<KrlProgramState> result = KrlVerifier.Verify([("prog.src", $"DEF prog( )\n  DECL INT i\n{body}END\n")], [], options);

        Assert.False(result.Finished);
        Assert.Equal("the program ran more than 100,000 statements and loop turns (the verification's step budget): an endless loop? (prog.src, line 3)", result.Error);
    }

    [Fact]
    public void AForLoopUpToTheLargestInt_Ends()
    {
        // The counter wrapped round to a negative INT before, so the loop never ended.
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", "DEF prog( )\n  DECL INT i\n  n = 0\n  FOR i = 2147483645 TO 2147483647\n    n = n + 1\n  ENDFOR\nEND\n"),
            ("prog.dat", "DEFDAT prog\nDECL INT n\nENDDAT\n"));

        Assert.Equal(KrlProgramState.Finished, twin.Run());
        Assert.Equal(3, twin.Modules["prog"].Data["n"].Value);
    }

    [Fact]
    public void AFilePastTheSizeLimit_IsRefusedBeforeItIsRead()
    {
        string folder = Directory.CreateTempSubdirectory("machina-krl-limits").FullName;
        try
        {
            string file = Path.Combine(folder, "prog.src");
            File.WriteAllText(file, "DEF prog( )\n" + Repeat("  ; a comment line of the program\n", 100) + "END\n");
            var twin = new KrlTwinController(new KrlTwinOptions { Limits = TwinLimits.Default with { MaxProgramChars = 1_000 } });

            KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.LoadFrom(file));

            Assert.Equal("prog.src, line 1: the file is larger than 1000 bytes (the twin's limit)", ex.Message);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void TheSmallestIntDividedByMinusOne_IsTheProgramsError_NotAnOverflowException()
    {
        string error = Failed("DEF prog( )\n  DECL INT i\n  i = -2147483647 - 1\n  i = i / -1\nEND\n");

        Assert.Equal("Arithmetic overflow: -2147483648 / -1 is not an INT (prog.src, line 4)", error);
    }

    [Fact]
    public void AnExponentWithoutDigits_IsRefusedAtLoad_NotAnException()
    {
        // Found by the fuzz run: double.Parse threw FormatException for "1E-" out of the parser.
        KrlLoadException ex = Refused("DEF prog( )\n  DECL REAL r\n  r = 1E-\nEND\n");

        Assert.Equal(3, ex.Line);
        Assert.EndsWith("is not a REAL number", ex.Reason, StringComparison.Ordinal);
    }
}

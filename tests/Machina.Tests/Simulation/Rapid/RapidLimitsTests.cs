using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// The RAPID twin's budgets (issue 40): each module here ended the process before (a stack overflow, an unhandled
/// <see cref="OverflowException"/>, an 11 GB array, a verification that never ended; checked with <c>machina verify</c> on the build
/// before the budgets), and is now the module's load error or the task's execution error, with its line.
/// </summary>
public class RapidLimitsTests
{
    private static string Module(string body, string data = "") => $"MODULE T\n{data}PROC main()\n{body}ENDPROC\nENDMODULE\n";

    private static RapidLoadException Refused(string module, TwinLimits? limits = null) =>
        Assert.Throws<RapidLoadException>(() => new RapidTwinController(new RapidTwinOptions { Limits = limits ?? TwinLimits.Default }).Load(("T.mod", module)));

    private static RapidTwinController Run(string module, TwinLimits? limits = null)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Limits = limits ?? TwinLimits.Default });
        twin.Load(("T.mod", module));
        Assert.Equal(RapidProgramState.Failed, twin.Run());
        return twin;
    }

    private static string Repeat(string text, int count) => string.Concat(Enumerable.Repeat(text, count));

    [Fact]
    public void ASumOf20000Terms_IsRefusedAtLoad()
    {
        RapidLoadException ex = Refused(Module($"  x := 1{Repeat("+1", 19_999)};\n", "VAR num x;\n"));

        Assert.Equal("Load error: line 4: Syntax error: the statement has more than 2000 operators and calls", ex.Message);
    }

    [Fact]
    public void FiftyThousandMinuses_AreRefusedAtLoad()
    {
        RapidLoadException ex = Refused(Module($"  x := {Repeat("-", 50_000)}1;\n", "VAR num x;\n"));

        Assert.Equal("Load error: line 4: Syntax error: the module is nested more than 100 levels deep (brackets, signs and blocks)", ex.Message);
    }

    [Theory]
    [InlineData("46341,46341", "{46341,46341}")]
    [InlineData("100000,100000", "{100000,100000}")]
    [InlineData("1E12", "{2147483647}")]
    public void AnArrayPastTheElementLimit_IsRefusedAtLoad(string sizes, string shown)
    {
        RapidLoadException ex = Refused(Module("  x := 1;\n", $"VAR num x;\nVAR num a{{{sizes}}};\n"));

        Assert.Equal($"Load error: line 3: Type error: 'a': the array {shown} has more than 1,000,000 elements (the twin's limit)", ex.Message);
    }

    [Fact]
    public void ALocalArrayPastTheElementLimit_IsRefusedAtLoad()
    {
        RapidLoadException ex = Refused("MODULE T\nPROC main()\n  VAR num a{1001,1000};\n  a{1,1} := 1;\nENDPROC\nENDMODULE\n");

        Assert.Equal("Load error: line 3: Type error: 'a': the array {1001,1000} has more than 1,000,000 elements (the twin's limit)", ex.Message);
    }

    [Fact]
    public void ModuleDataPastTheTotal_IsRefusedAtLoad()
    {
        string data = string.Concat(Enumerable.Range(1, 5).Select(i => $"VAR num a{i}{{1000000}};\n"));

        RapidLoadException ex = Refused(Module("  a1{1} := 1;\n", data));

        Assert.Equal("Load error: line 6: Type error: the data of the modules hold more than 4,000,000 array elements (the twin's limit)", ex.Message);
    }

    [Fact]
    public void RecursionWithLocalArrays_StopsAtTheTotal_AndNoHandlerTakesIt()
    {
        RapidTwinController twin = Run("MODULE T\nPROC r()\n  VAR num a{100000};\n  r;\nERROR\n  TRYNEXT;\nENDPROC\nPROC main()\n  r;\nENDPROC\nENDMODULE\n");

        Assert.Equal("Execution error: line 3: the routines' local data hold more than 4,000,000 array elements (the twin's limit) (task T_ROB1)", twin.Error);
    }

    [Fact]
    public void EndlessRecursion_StopsAtTheCallDepth_EvenWithAnErrorHandler()
    {
        RapidTwinController twin = Run("MODULE T\nPROC r()\n  r;\nERROR\n  RETRY;\nENDPROC\nPROC main()\n  r;\nENDPROC\nENDMODULE\n");

        Assert.Equal("Execution error: line 3: the routine calls are nested deeper than 200 levels (task T_ROB1)", twin.Error);
    }

    [Fact]
    public void RecursionThroughDeepExpressions_OnASmallStack_IsTheTasksStackOverflow()
    {
        string nested = Repeat("0 + (", 95) + "f(n + 1)" + Repeat(")", 95);
        string module = $"MODULE T\nFUNC num f(num n)\n  IF n > 150 THEN\n    RETURN 0;\n  ENDIF\n  RETURN {nested};\nENDFUNC\nPROC main()\n  TPWrite \"\" \\Num:=f(0);\nENDPROC\nENDMODULE\n";
        string? error = null;
        var thread = new Thread(() => error = Run(module).Error, 512 * 1024);
        thread.Start();
        Assert.True(thread.Join(TimeSpan.FromMinutes(2)));

        // The stack runs out in the IF's condition (line 3) or in the RETURN's expression (line 6): which of the two checks sees it
        // first depends on the frame sizes the JIT chose for the interpreter's methods (the same code, tiered up or not, in a run of
        // the whole suite), so both lines are the task's true answer; the message and the task are not.
        Assert.NotNull(error);
        Assert.Matches(@"^Execution error: line (3|6): stack overflow: the routine calls and expressions are nested too deeply \(task T_ROB1\)$", error);
    }

    [Theory]
    [InlineData("  WHILE TRUE DO\n  ENDWHILE\n", 3)]
    [InlineData("  FOR i FROM 1 TO 1E12 DO\n  ENDFOR\n", 3)]
    [InlineData("  top:\n  GOTO top;\n", 3)]
    public void AnEndlessLoop_InAVerification_StopsAtTheStepBudget(string body, int line)
    {
        var options = new RapidTwinOptions { Limits = TwinLimits.Verify with { MaxSteps = 100_000 } };

        TwinVerification<RapidProgramState> result = RapidVerifier.Verify([("T.mod", Module(body))], [], options);

        Assert.False(result.Finished);
        Assert.Equal($"Execution error: line {line}: the task ran more than 100,000 statements and loop turns (the verification's step budget): an endless loop? (task T_ROB1)", result.Error);
    }

    [Fact]
    public void AModuleFilePastTheSizeLimit_IsRefusedBeforeItIsRead()
    {
        string folder = Directory.CreateTempSubdirectory("machina-rapid-limits").FullName;
        try
        {
            string file = Path.Combine(folder, "T.mod");
            File.WriteAllText(file, Module(Repeat("  ! a comment line of the module\n", 100)));
            var twin = new RapidTwinController(new RapidTwinOptions { Limits = TwinLimits.Default with { MaxProgramChars = 1_000 } });

            RapidLoadException ex = Assert.Throws<RapidLoadException>(() => twin.LoadFrom(file));

            Assert.Equal("T.mod", ex.Module);
            Assert.Equal("Load error: line 1: Syntax error: the module file is larger than 1000 bytes (the twin's limit)", ex.Message);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }
}

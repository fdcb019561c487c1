using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// The URScript twin's budgets (issue 40): each program here ended the process before (a stack overflow, 2 GB of string, thousands
/// of threads, a verification that never ended; checked with <c>machina verify</c> on the build before the budgets), and is now
/// the program's error, with its line.
/// </summary>
public class UrLimitsTests
{
    private static (UrProgramState State, string? Error) Run(string program, TwinLimits? limits = null)
    {
        using var twin = new UrTwinController(new UrTwinOptions { Limits = limits ?? TwinLimits.Default });
        UrProgramState state = twin.Run(program, CancellationToken.None);
        return (state, twin.Error);
    }

    private static string Repeat(string text, int count) => string.Concat(Enumerable.Repeat(text, count));

    [Fact]
    public void TenThousandBrackets_AreACompileError_NotAStackOverflow()
    {
        (UrProgramState state, string? error) = Run($"def p():\n  y = {Repeat("(", 10_000)}1{Repeat(")", 10_000)}\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Compile error: line 2: the program is nested more than 100 levels deep (brackets, signs and blocks)", error);
    }

    [Fact]
    public void ASumOf200000Terms_IsACompileError()
    {
        (UrProgramState state, string? error) = Run($"def p():\n  y = 1{Repeat("+1", 199_999)}\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Compile error: line 2: the statement has more than 2000 operators and calls", error);
    }

    [Fact]
    public void ASumWithinTheBudget_Runs()
    {
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run($"def p():\n  y = 1{Repeat("+1", 1_999)}\n  textmsg(y)\nend\n", CancellationToken.None);

        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal(["2000"], twin.Pendant.Lines);
    }

    [Fact]
    public void EndlessRecursion_StopsAtTheCallDepth()
    {
        (UrProgramState state, string? error) = Run("def p():\n  def f(n):\n    return f(n + 1)\n  end\n  f(0)\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Runtime error: line 3: too many nested calls (more than 200) in 'f'", error);
    }

    [Fact]
    public void RecursionThroughDeepExpressions_OnASmallStack_IsTheProgramsStackOverflow()
    {
        // 95 nested additions around each of 200 calls: far more .NET frames than a 512 KB thread holds. Before the stack guard
        // this ended the test host; now the program stops with its error.
        string nested = Repeat("0 + (", 95) + "f(n + 1)" + Repeat(")", 95);
        string program = $"def p():\n  def f(n):\n    if n > 150:\n      return 0\n    end\n    return {nested}\n  end\n  f(0)\nend\n";
        (UrProgramState State, string? Error) result = default;
        var thread = new Thread(() => result = Run(program), 512 * 1024);
        thread.Start();
        Assert.True(thread.Join(TimeSpan.FromMinutes(2)));

        Assert.Equal(UrProgramState.Failed, result.State);
        Assert.Equal("Runtime error: line 6: stack overflow: the calls and expressions are nested too deeply", result.Error);
    }

    [Fact]
    public void StrCatDoubling_StopsAtTheStringLimit()
    {
        (UrProgramState state, string? error) = Run("def p():\n  s = \"ab\"\n  i = 0\n  while i < 40:\n    s = str_cat(s, s)\n    i = i + 1\n  end\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Runtime error: line 5: str_cat: the string would be longer than 1048576 characters (the twin's limit)", error);
    }

    [Fact]
    public void ToStrOfAListOfLongStrings_StopsAtTheStringLimit()
    {
        (UrProgramState state, string? error) = Run(
            "def p():\n  s = \"ab\"\n  i = 0\n  while i < 18:\n    s = str_cat(s, s)\n    i = i + 1\n  end\n  t = to_str([s, s, s, s])\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Runtime error: line 8: to_str: the string would be longer than 1048576 characters (the twin's limit)", error);
    }

    [Fact]
    public void RunInALoop_StopsAtTheThreadLimit()
    {
        (UrProgramState state, string? error) = Run(
            "def p():\n  thread t():\n    sleep(100)\n  end\n  i = 0\n  while i < 5000:\n    h = run t()\n    i = i + 1\n  end\nend\n");

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Runtime error: line 7: more than 64 threads are running (the twin's limit): join or kill one before starting 't'", error);
    }

    [Fact]
    public void ThreadsThatEnd_FreeTheirPlace()
    {
        (UrProgramState state, string? error) = Run(
            "def p():\n  thread t():\n    sync()\n  end\n  i = 0\n  while i < 200:\n    h = run t()\n    join h\n    i = i + 1\n  end\nend\n");

        Assert.True(state == UrProgramState.Finished, error);
    }

    [Fact]
    public void WhileTrue_InAVerification_StopsAtTheStepBudget()
    {
        var options = new UrTwinOptions { Limits = TwinLimits.Verify with { MaxSteps = 100_000 } };

        TwinVerification<UrProgramState> result = UrScriptVerifier.Verify("def p():\n  while True:\n    x = 1\n  end\nend\n", [], options);

        Assert.False(result.Finished);
        Assert.Equal("Runtime error: line 3: the program ran more than 100,000 statements (the verification's step budget): an endless loop?", result.Error);
    }

    [Fact]
    public void TheVerifierDefault_HasAStepBudget_AndAServingTwinHasNone()
    {
        Assert.Equal(50_000_000, TwinLimits.Verify.MaxSteps);
        Assert.Equal(0, new UrTwinOptions().Limits.MaxSteps);
    }

    [Fact]
    public void AProgramPastTheSizeLimit_IsRefusedBeforeParsing()
    {
        var limits = TwinLimits.Default with { MaxProgramChars = 1_000 };

        UrCompileException ex = Assert.Throws<UrCompileException>(() => UrTwinController.Compile("def p():\n" + Repeat("  x = 1\n", 200) + "end\n", limits));

        Assert.Equal("Compile error: line 1: the program is longer than 1000 characters", ex.Message);
    }

    [Fact]
    public void BlocksNestedPastTheLimit_AreACompileError()
    {
        string program = "def p():\n" + Repeat("if True:\n", 120) + "x = 1\n" + Repeat("end\n", 120) + "end\n";

        (UrProgramState state, string? error) = Run(program);

        Assert.Equal(UrProgramState.Failed, state);
        Assert.Equal("Compile error: line 101: the program is nested more than 100 levels deep (brackets, signs and blocks)", error);
    }

    [Fact]
    public void TheSmallestIntModuloMinusOne_IsZero_NotAnOverflowException()
    {
        // Found by the fuzz run: .NET throws OverflowException for -2147483648 % -1, which ended the process hosting the twin.
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("def p():\n  x = -2147483648\n  textmsg(x % -1)\nend\n", CancellationToken.None);

        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal(["0"], twin.Pendant.Lines);
    }
}

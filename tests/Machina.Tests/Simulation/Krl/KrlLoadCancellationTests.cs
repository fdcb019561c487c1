using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Loading a KRL file observes the caller's cancellation (issue 40). The fuzz run's KRL cases that stopped 3 to 19 s after
/// their 2 s deadline were files of megabytes refused at load (a syntax error on a line of 4-28 KB, 200 such lines): reading
/// them took about a second of processor time, many seconds on the loaded machine, and nothing could stop it. The lexer and
/// the parser now look at the token at every line.
/// </summary>
public class KrlLoadCancellationTests
{
    /// <summary>A program of <paramref name="lines"/> assignments whose last line has a character KRL does not have.</summary>
    private static string LongProgramWrongAtTheEnd(int lines) =>
        "DEF prog( )\n  DECL INT x\n" + string.Concat(Enumerable.Repeat("  x = x + 1\n", lines)) + "  x = #\nEND\n";

    [Fact]
    public void Load_WithoutCancellation_ReadsToTheEndAndRefusesTheLastLine()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions());

        KrlLoadException refused = Assert.Throws<KrlLoadException>(() => twin.Load(("prog.src", LongProgramWrongAtTheEnd(100_000))));

        Assert.Equal(100_003, refused.Line);
    }

    [Fact]
    public void Load_Cancelled_StopsBeforeTheEndAndLoadsNothing()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions());
        using var cancelled = new CancellationTokenSource();
        cancelled.Cancel();

        // Stopped at its first line: the syntax error at the end is never reached.
        Assert.Throws<OperationCanceledException>(() => twin.Load(cancelled.Token, ("prog.src", LongProgramWrongAtTheEnd(100_000))));
        Assert.Throws<OperationCanceledException>(() => twin.Load(cancelled.Token, ("prog.src", "DEF prog( )\nEND\n")));
        Assert.Empty(twin.Modules);
    }

    [Fact]
    public void Load_NotCancelled_LoadsAsBefore()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions());
        using var live = new CancellationTokenSource();

        twin.Load(live.Token, ("prog.src", "DEF prog( )\n  DECL INT x\n  x = 2\nEND\n"));

        Assert.Equal(KrlProgramState.Finished, twin.Run());
        Assert.Contains("prog", twin.Modules.Keys);
    }
}

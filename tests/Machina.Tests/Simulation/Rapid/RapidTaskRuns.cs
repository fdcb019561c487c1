using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>Runs every loaded task of a twin to its end (bounded), stopping them whatever happens.</summary>
internal static class RapidTaskRuns
{
    /// <summary>Starts the tasks and asserts they all end within <paramref name="seconds"/>; the tasks are stopped in any case.</summary>
    public static void RunToEnd(RapidTwinController twin, double seconds)
    {
        twin.StartTasks();
        try
        {
            Assert.True(twin.StopTasksWhenEnded(TimeSpan.FromSeconds(seconds)), string.Join(" | ", twin.Pendant.Lines));
        }
        finally
        {
            twin.StopTasks(TimeSpan.FromSeconds(10));
        }
    }

    /// <summary>
    /// Runs <paramref name="body"/> as main (after <paramref name="data"/>) with a handler that writes "ERR_ARGVALERR TRUE" (or FALSE)
    /// for each error and goes on with the next statement; returns the pendant's lines.
    /// </summary>
    public static IReadOnlyList<string> ArgumentErrors(string data, string body)
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", $"MODULE T\n{data}\n  PROC main()\n{body}\n  ERROR\n    TPWrite \"ERR_ARGVALERR \" \\Bool:=ERRNO = ERR_ARGVALERR;\n    TRYNEXT;\n  ENDPROC\nENDMODULE\n"));
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }
}

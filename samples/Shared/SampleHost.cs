// Shared by every sample (linked into each project): runs a sample's RunAsync as a console program.
using Machina;

/// <summary>
/// The console side of a sample: Ctrl+C cancels it, its output goes to the terminal, and anything unexpected becomes a
/// clear message and a non-zero exit code instead of a crash. The sample itself is a public <c>RunAsync(args, output,
/// error, cancellationToken)</c> method, which the test suite calls directly (tests/Machina.Tests/Samples).
/// </summary>
internal static class SampleHost
{
    /// <summary>Exit code of a sample that did what it shows.</summary>
    public const int Ok = 0;

    /// <summary>Exit code of a sample that failed (the robot link, an unexpected result); the message says why.</summary>
    public const int Failed = 1;

    /// <summary>Exit code of a sample given wrong command-line arguments (it prints its usage).</summary>
    public const int Usage = 2;

    /// <summary>
    /// Runs <paramref name="sample"/> with the console's streams; Ctrl+C cancels it, and so does any key when
    /// <paramref name="anyKeyStops"/> (and the keyboard is there).
    /// </summary>
    public static async Task<int> RunAsync(string[] args, Func<string[], TextWriter, TextWriter, CancellationToken, Task<int>> sample, bool anyKeyStops = false)
    {
        using var cancellation = new CancellationTokenSource();
        Console.CancelKeyPress += (_, e) =>
        {
            e.Cancel = true;   // let the sample stop cleanly (disconnect, stop the virtual controller)
            cancellation.Cancel();
        };
        if (anyKeyStops && !Console.IsInputRedirected)
        {
            Console.WriteLine("Press any key to stop.");
            _ = Task.Run(() =>
            {
                Console.ReadKey(intercept: true);
                cancellation.Cancel();
            });
        }
        try
        {
            return await sample(args, Console.Out, Console.Error, cancellation.Token);
        }
        catch (OperationCanceledException) when (cancellation.IsCancellationRequested)
        {
            Console.Error.WriteLine("Stopped (Ctrl+C).");
            return Failed;
        }
        catch (Exception ex)
        {
            // Whatever a sample did not expect: say what went wrong, without a stack trace.
            return Fail(Console.Error, $"{ex.GetType().Name}: {ex.Message}");
        }
    }

    /// <summary>Prints why a sample failed, for someone who is not a programmer, and returns <see cref="Failed"/>.</summary>
    public static int Fail(TextWriter error, string message)
    {
        error.WriteLine("FAILED: " + message);
        return Failed;
    }

    /// <summary>Prints the failure of the robot link (<see cref="MachinaException"/>) and returns <see cref="Failed"/>.</summary>
    public static int LinkFailed(TextWriter error, MachinaException ex) => Fail(error, $"the robot link failed: {ex.Message}");
}

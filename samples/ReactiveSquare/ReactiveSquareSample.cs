// The paper's reactive loop (Code Sample 7): whenever the robot has nothing left to do, issue another 50 x 50 mm square.
// Runs against a virtual ABB controller by default (or --host/--port for a real one) and stops cleanly after
// --loops squares (default 3) or, after the current square, when cancelled (a key or Ctrl+C in the console).
namespace Machina.Samples;

/// <summary>The reactive square sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class ReactiveSquareSample
{
    /// <summary>
    /// Runs the sample: 0 when the squares were drawn, 1 when the robot link failed, 2 for wrong arguments. Cancelling
    /// <paramref name="cancellationToken"/> stops it after the square being drawn, cleanly.
    /// </summary>
    public static async Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        int loops = 3;
        await using SampleController? controller = await SampleController.OpenAsync(
            args, "ReactiveSquare [--loops <squares>] [--brand abb|ur|kuka] [--host <controller address> --port <driver port>]", speedFactor: 8, output, error,
            (name, value) => name == "--loops" && int.TryParse(value, out loops) && loops > 0);
        if (controller is null)
        {
            return SampleHost.Usage;
        }

        try
        {
            var bot = Robot.Create("ReactiveSquare", controller.Brand);
            bot.ControlMode("online");
            await bot.ConnectAsync(controller.Host, controller.Port, cancellationToken);

            var finished = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
            int squares = 0, started = 0, lastOfSquare = 0;
            var gate = new object();   // makes "issue a square" and "remember its last id" one step

            void Square()
            {
                lock (gate)
                {
                    started++;
                    bot.Move(50, 0, 0);
                    bot.Move(0, 50, 0);
                    bot.Move(-50, 0, 0);
                    bot.Move(0, -50, 0);
                    lastOfSquare = bot.GetIssuedState().LastAction!.Id;
                }
            }

            // Raised on the robot's event thread; issuing from here is allowed.
            bot.ActionExecuted += (_, e) =>
            {
                lock (gate)
                {
                    OnExecuted(e);
                }
            };

            void OnExecuted(ActionExecutedArgs e)
            {
                // Nothing pending after the last action of the square. (A fast controller may also finish an earlier move of the
                // square before the next one is issued; checking the id keeps that from starting a second square.)
                if (e.PendingExecutionTotal != 0 || e.LastAction.Id != lastOfSquare || finished.Task.IsCompleted)
                {
                    return;
                }
                if (started > squares)
                {
                    squares++;
                    output.WriteLine($"Square {squares} done, tool at {e.Position}.");
                }
                if (squares >= loops || cancellationToken.IsCancellationRequested)
                {
                    finished.TrySetResult();
                    return;
                }
                Square();
            }

            bot.ConnectionLost += (_, e) => finished.TrySetException(e.Error);

            lock (gate)
            {
                bot.SpeedTo(100);
                bot.MoveTo(400, 0, 400);   // squares start here; executing it triggers the first square
                lastOfSquare = bot.GetIssuedState().LastAction!.Id;
            }

            await finished.Task.WaitAsync(TimeSpan.FromMinutes(10), CancellationToken.None);
            await bot.WaitForCompletionAsync(CancellationToken.None);
            output.WriteLine($"Stopped after {squares} squares at {bot.GetCurrentPosition()}.");
            await bot.DisconnectAsync();
            return SampleHost.Ok;
        }
        catch (MachinaException ex)
        {
            return SampleHost.LinkFailed(error, ex);
        }
        catch (TimeoutException)
        {
            return SampleHost.Fail(error, "the squares did not finish within 10 minutes.");
        }
    }
}

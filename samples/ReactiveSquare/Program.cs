// The paper's reactive loop (Code Sample 7): whenever the robot has nothing left to do, issue another 50 x 50 mm square.
// Runs against a virtual ABB controller by default (or --host/--port for a real one) and stops cleanly after
// --loops squares (default 3) or when a key is pressed.
using Machina;

int loops = 3;
await using SampleController? controller = await SampleController.OpenAsync(
    args, "ReactiveSquare [--loops <squares>] [--host <controller address> --port <driver port>]", speedFactor: 8,
    (name, value) => name == "--loops" && int.TryParse(value, out loops) && loops > 0);
if (controller is null)
{
    return 2;
}

try
{
    var bot = Robot.Create("ReactiveSquare", controller.Brand);
    bot.ControlMode("online");
    await bot.ConnectAsync(controller.Host, controller.Port);

    var finished = new TaskCompletionSource(TaskCreationOptions.RunContinuationsAsynchronously);
    int squares = 0, started = 0, lastOfSquare = 0;
    bool stopRequested = false;
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
            Console.WriteLine($"Square {squares} done, tool at {e.Position}.");
        }
        if (squares >= loops || Volatile.Read(ref stopRequested))
        {
            finished.TrySetResult();
            return;
        }
        Square();
    }

    bot.ConnectionLost += (_, e) => finished.TrySetException(e.Error);

    if (!Console.IsInputRedirected)
    {
        Console.WriteLine("Press any key to stop after the current square.");
        _ = Task.Run(() =>
        {
            Console.ReadKey(intercept: true);
            Volatile.Write(ref stopRequested, true);
        });
    }

    lock (gate)
    {
        bot.SpeedTo(100);
        bot.MoveTo(400, 0, 400);   // squares start here; executing it triggers the first square
        lastOfSquare = bot.GetIssuedState().LastAction!.Id;
    }

    await finished.Task.WaitAsync(TimeSpan.FromMinutes(10));
    await bot.WaitForCompletionAsync();
    Console.WriteLine($"Stopped after {squares} squares at {bot.GetCurrentPosition()}.");
    await bot.DisconnectAsync();
    return 0;
}
catch (MachinaException ex)
{
    Console.Error.WriteLine($"The robot link failed: {ex.Message}");
    return 1;
}

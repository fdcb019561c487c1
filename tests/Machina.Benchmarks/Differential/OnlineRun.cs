using Machina.Simulation;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Benchmarks.Differential;

/// <summary>
/// Half (b) of the differential property: the program streamed online through Machina's driver to the brand's virtual
/// controller (the same twin, running drivers/abb, drivers/ur or drivers/kuka), the way <c>machina run --sim</c> does it:
/// connect, the pre-check of every action (what the driver cannot stream, what the arm cannot reach) before anything is sent,
/// then every action issued and waited for. Instant execution, loopback, OS-chosen ports, the controller stopped at the end.
/// </summary>
internal static class OnlineRun
{
    /// <summary>The longest one program may take, end to end, on a loaded machine.</summary>
    internal static readonly TimeSpan Limit = TimeSpan.FromSeconds(60);

    /// <summary>Streams <paramref name="actions"/> to a virtual controller of <paramref name="brand"/> whose arm starts at <paramref name="start"/>.</summary>
    internal static async Task<TwinRun> RunAsync(RobotType brand, IReadOnlyList<RobotAction> actions, Joints start, CancellationToken cancellation)
    {
        using var timeout = CancellationTokenSource.CreateLinkedTokenSource(cancellation);
        timeout.CancelAfter(Limit);
        CancellationToken token = timeout.Token;
        RobotModel model = DifferentialPrograms.Model(brand);
        await using Controller controller = await Controller.StartAsync(brand, model, start, token).ConfigureAwait(false);
        Robot robot = Robot.Create("Differential", brand, model);
        robot.ControlMode(ControlType.Online);
        robot.ConnectTimeout = Limit;
        await robot.ConnectAsync("127.0.0.1", controller.Port, token).ConfigureAwait(false);
        try
        {
            if (PreCheck(robot, actions) is TwinRun refused)
            {
                return refused with { Steps = controller.Steps() };
            }
            for (int i = 0; i < actions.Count; i++)
            {
                try
                {
                    robot.Issue(actions[i]);
                }
                catch (ActionRefusedException ex)
                {
                    return new TwinRun(TwinRunEnd.Refused, $"issued after the pre-check passed, refused: {ex.Message}", i, controller.Steps());
                }
            }
            try
            {
                await robot.WaitForCompletionAsync(token).ConfigureAwait(false);
            }
            catch (ActionFailedException failure)
            {
                int at = IndexOf(actions, failure.Action);
                return new TwinRun(TwinRunEnd.Stopped, $"{failure.ControllerReason} (code {failure.ControllerCode})", at < 0 ? null : at, controller.Steps());
            }
            catch (MachinaException lost)
            {
                return new TwinRun(TwinRunEnd.Stopped, $"{lost.GetType().Name}: {lost.Message}", null, controller.Steps());
            }
            return new TwinRun(TwinRunEnd.Finished, null, null, controller.Steps());
        }
        finally
        {
            await robot.DisconnectAsync().ConfigureAwait(false);
        }
    }

    /// <summary>What <c>machina run</c> checks once connected and before it sends anything (RunCheck): the first problem, or null.</summary>
    private static TwinRun? PreCheck(Robot robot, IReadOnlyList<RobotAction> actions)
    {
        ProgramTrial trial = robot.StartTrial();
        for (int i = 0; i < actions.Count; i++)
        {
            TrialStep step = trial.Try(actions[i]);
            if (step.Refusal is string refusal)
            {
                return new TwinRun(TwinRunEnd.Refused, refusal, i, []);
            }
            if (step.Blocking is KinematicIssue issue)
            {
                return new TwinRun(TwinRunEnd.Unreachable, issue.Reason, i, []);
            }
        }
        return null;
    }

    private static int IndexOf(IReadOnlyList<RobotAction> actions, RobotAction action)
    {
        for (int i = 0; i < actions.Count; i++)
        {
            if (ReferenceEquals(actions[i], action))
            {
                return i;
            }
        }
        return -1;
    }

    /// <summary>One brand's virtual controller and the trace of its twin's arm.</summary>
    private sealed class Controller(IAsyncDisposable inner, int port, Func<IEnumerable<TwinTraceEntry>?> trace) : IAsyncDisposable
    {
        internal int Port => port;

        /// <summary>The motions and outputs the twin's arm did (the KRL twin's BCO runs left out, as <c>machina verify</c> leaves them).</summary>
        internal List<TwinTraceEntry> Steps() => TwinRun.StepsOf((trace() ?? []).Where(e => !e.Text.EndsWith(KrlTwinController.BcoRun, StringComparison.Ordinal)));

        internal static async Task<Controller> StartAsync(RobotType brand, RobotModel model, Joints start, CancellationToken token)
        {
            switch (brand)
            {
                case RobotType.UR:
                    var ur = new VirtualUrController(new VirtualUrControllerOptions { Model = model, InitialJoints = start, InstantExecution = true });
                    await Started(ur, ur.StartAsync(token)).ConfigureAwait(false);
                    return new Controller(ur, ur.Port, () => ur.Twin.Arm.Trace);
                case RobotType.KUKA:
                    var kuka = new VirtualKukaController(new VirtualKukaControllerOptions { Model = model, InitialJoints = start, InstantExecution = true });
                    await Started(kuka, kuka.StartAsync(token)).ConfigureAwait(false);
                    return new Controller(kuka, kuka.Port, () => kuka.Twin?.Arm.Trace);
                default:
                    var abb = new VirtualAbbController(new VirtualAbbControllerOptions { Model = model, InitialJoints = start, InstantExecution = true });
                    await Started(abb, abb.StartAsync(token)).ConfigureAwait(false);
                    return new Controller(abb, abb.Port, () => abb.Twin?.Arm.Trace);
            }
        }

        private static async Task Started(IAsyncDisposable controller, Task start)
        {
            try
            {
                await start.ConfigureAwait(false);
            }
            catch
            {
                await controller.DisposeAsync().ConfigureAwait(false);
                throw;
            }
        }

        public ValueTask DisposeAsync() => inner.DisposeAsync();
    }
}

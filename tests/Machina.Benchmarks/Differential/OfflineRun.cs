using Machina.Simulation.Krl;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Benchmarks.Differential;

/// <summary>
/// Half (a) of the differential property: the program compiled for the brand and run on its twin the way <c>machina verify</c>
/// does it (the brand's compiler with the default options, the twin of the same arm starting at the first motion's target,
/// the named outputs the program sets configured), keeping the twin's trace.
/// </summary>
internal static class OfflineRun
{
    /// <summary>Compiles <paramref name="actions"/> for <paramref name="brand"/> and runs them on its twin, starting at <paramref name="start"/>.</summary>
    internal static TwinRun Run(RobotType brand, IReadOnlyList<RobotAction> actions, Joints start, CancellationToken cancellation)
    {
        RobotModel model = DifferentialPrograms.Model(brand);
        RobotProgram program = Compilers.For(brand).Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model });
        List<(string Name, string Text)> Files(params string[] extensions) => [.. program.Files
            .Where(f => extensions.Any(e => f.Extension.Equals(e, StringComparison.OrdinalIgnoreCase))).Select(f => (f.FileName, f.ToText("\n")))];
        return brand switch
        {
            RobotType.UR => Ur(Files("script")[0].Text, model, start, cancellation),
            RobotType.KUKA => Krl(Files("src", "dat"), actions, model, start, cancellation),
            _ => Rapid(Files("mod"), actions, model, start, cancellation),
        };
    }

    /// <summary>
    /// Where both runs start: where <c>machina verify</c> puts the arm (the first motion's target, in the solution nearest the
    /// twin's default start), or the twin's default start when the program has no motion.
    /// </summary>
    internal static Joints StartOf(RobotType brand, IReadOnlyList<RobotAction> actions)
    {
        RobotModel model = DifferentialPrograms.Model(brand);
        Joints near = brand switch
        {
            RobotType.UR => new UrTwinOptions().StartJoints,
            RobotType.KUKA => new KrlTwinOptions().StartJoints,
            _ => new RapidTwinOptions().StartJoints,
        };
        return TwinComparison.StartOf(TwinComparison.Expect(actions, model, _ => null), model, near) ?? near;
    }

    private static TwinRun Ur(string script, RobotModel model, Joints start, CancellationToken cancellation)
    {
        using var twin = new UrTwinController(new UrTwinOptions { Model = model, StartJoints = start });
        UrProgramState state = twin.Run(script, cancellation);
        return Ended(state == UrProgramState.Finished, twin.Error, twin.Arm.Trace);
    }

    /// <summary>The RAPID twin with the signals the program sets, waits for and reads declared, as <c>machina verify</c> declares them.</summary>
    private static TwinRun Rapid(List<(string Name, string Text)> modules, IReadOnlyList<RobotAction> actions, RobotModel model, Joints start, CancellationToken cancellation)
    {
        IEnumerable<(string, string)> signals = RapidVerifier.SignalsOf(actions);
        var twin = new RapidTwinController(new RapidTwinOptions { Model = model, StartJoints = start, Signals = [.. signals] });
        try
        {
            twin.Load([.. modules]);
        }
        catch (RapidLoadException ex)
        {
            return new TwinRun(TwinRunEnd.Stopped, $"{ex.Module}: {ex.Message}", null, []);
        }
        RapidProgramState state = twin.Run("main", cancellation);
        return Ended(state == RapidProgramState.Finished, twin.Error, twin.Arm.Trace);
    }

    private static TwinRun Krl(List<(string Name, string Text)> files, IReadOnlyList<RobotAction> actions, RobotModel model, Joints start, CancellationToken cancellation)
    {
        List<string> named = [.. actions.OfType<ActionIODigital>().Where(d => !d.IsDigit).Select(d => d.PinName).Distinct(StringComparer.OrdinalIgnoreCase)];
        using var twin = new KrlTwinController(new KrlTwinOptions
        {
            Model = model, StartJoints = start, Signals = [.. named.Select((n, i) => (n, KrlSystemVariables.DigitalCount - i))],
        });
        try
        {
            twin.Load([.. files]);
        }
        catch (KrlLoadException ex)
        {
            return new TwinRun(TwinRunEnd.Stopped, ex.Message, null, []);
        }
        KrlProgramState state = twin.Run(null, cancellation);
        return Ended(state == KrlProgramState.Finished, twin.Error, twin.Arm.Trace.Where(e => !e.Text.EndsWith(KrlTwinController.BcoRun, StringComparison.Ordinal)));
    }

    private static TwinRun Ended(bool finished, string? error, IEnumerable<TwinTraceEntry> trace) =>
        new(finished ? TwinRunEnd.Finished : TwinRunEnd.Stopped, finished ? null : error ?? "the program was stopped", null, TwinRun.StepsOf(trace));
}

using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Runs a compiled RAPID program's <c>main</c> on the twin controller and compares, step by step, the poses the arm reached and
/// the outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class RapidVerifier
{
    /// <summary>Largest position difference accepted, in mm (targets carry 1 µm).</summary>
    public const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted, in degrees (quaternions are written with 4 decimals).</summary>
    public const double AngleToleranceDegrees = 0.05;

    private sealed record Expectation(RobotAction Action, TwinTraceKind Kind, RobotState State, string? Output);

    /// <summary>Loads <paramref name="modules"/> on a twin with <paramref name="options"/>, runs main and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<RapidProgramState> Verify(IReadOnlyList<(string Name, string Text)> modules, IEnumerable<RobotAction> actions,
        RapidTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new RapidTwinOptions();
        List<RobotAction> all = [.. actions];
        List<Expectation> expected = Expect(all, options.Model);
        options = new RapidTwinOptions
        {
            Model = options.Model, StartJoints = StartOf(expected, options) ?? options.StartJoints, Time = options.Time,
            RealTime = options.RealTime, Acceleration = options.Acceleration,
            Signals = [.. options.Signals, .. SignalsOf(all).Where(s => !options.Signals.Any(o => o.Name.Equals(s.Name, StringComparison.OrdinalIgnoreCase)))],
        };
        var twin = new RapidTwinController(options);
        RapidProgramState state;
        string? error;
        try
        {
            twin.Load([.. modules]);
            state = twin.Run("main", cancellation);
            error = twin.Error;
        }
        catch (RapidLoadException ex)
        {
            state = RapidProgramState.Failed;
            error = ex.Module is null ? ex.Message : $"{ex.Module}: {ex.Message}";
        }
        List<TwinTraceEntry> done = [.. twin.Arm.Trace.Where(e => e.Kind is TwinTraceKind.Motion or TwinTraceKind.Output)];
        var result = new TwinVerification<RapidProgramState> { State = state, Finished = state == RapidProgramState.Finished, Error = error, Seconds = twin.Clock.Seconds };
        int count = Math.Max(expected.Count, done.Count);
        for (int i = 0; i < count; i++)
        {
            Expectation? e = i < expected.Count ? expected[i] : null;
            TwinTraceEntry? d = i < done.Count ? done[i] : null;
            string? problem = (e, d) switch
            {
                (null, _) => "the twin did a step that the actions do not have",
                (_, null) => state == RapidProgramState.Finished ? "the program ended before this step" : "the program stopped before this step",
                _ => Compare(e, d),
            };
            result.Steps.Add(new TwinVerifyStep(i + 1, e?.Action.ToInstruction(), d?.Line ?? 0, e is null ? "(no more actions)" : Describe(e),
                d is null ? "(the program did not get there)" : Describe(d), problem));
        }
        return result;
    }

    /// <summary>The named signals the actions set (numbered pins do not exist on an ABB controller and are not compiled).</summary>
    private static IEnumerable<(string Name, string Type)> SignalsOf(List<RobotAction> actions) => actions
        .Select(a => a switch
        {
            ActionIODigital d when !d.IsDigit => (d.PinName, "signaldo"),
            ActionIOAnalog an when !an.IsDigit => (an.PinName, "signalao"),
            _ => ((string, string)?)null,
        })
        .OfType<(string, string)>()
        .DistinctBy(s => s.Item1, StringComparer.OrdinalIgnoreCase);

    /// <summary>Where the arm starts: at the first motion's target, in the solution nearest to the options' start joints.</summary>
    private static Joints? StartOf(List<Expectation> expected, RapidTwinOptions options)
    {
        Expectation? first = expected.FirstOrDefault(e => e.Kind == TwinTraceKind.Motion);
        if (first is null)
        {
            return null;
        }
        if (first.Action is ActionAxes && first.State.Axes is { } axes)
        {
            return axes;
        }
        if (first.State.Position is not { } position || first.State.Rotation is not { } rotation)
        {
            return null;
        }
        Pose tool = first.State.Tool is { } t ? new Pose(t.TcpPosition, t.TcpOrientation) : Pose.Identity;
        return options.Model.Kinematics.Closest(new Pose(position, rotation) * tool.Inverse(), options.StartJoints);
    }

    private static List<Expectation> Expect(List<RobotAction> actions, RobotModel model)
    {
        var cursor = new RobotCursor { Model = model };
        var expected = new List<Expectation>();
        foreach (RobotAction action in actions)
        {
            if (cursor.TryApply(action) is not null)
            {
                continue;
            }
            switch (action)
            {
                case ActionTranslation or ActionRotation or ActionTransformation or ActionAxes or ActionArcMotion:
                    expected.Add(new Expectation(action, TwinTraceKind.Motion, cursor.Snapshot(), null));
                    break;
                case ActionIODigital io when !io.IsDigit:
                    expected.Add(new Expectation(action, TwinTraceKind.Output, cursor.Snapshot(), $"{io.PinName} = {(io.On ? 1 : 0)}"));
                    break;
                case ActionIOAnalog io when !io.IsDigit:
                    expected.Add(new Expectation(action, TwinTraceKind.Output, cursor.Snapshot(), $"{io.PinName} = {RapidValues.FormatNumber(Math.Round(io.Value, 6))}"));
                    break;
            }
        }
        return expected;
    }

    private static string? Compare(Expectation e, TwinTraceEntry d)
    {
        if (e.Kind != d.Kind)
        {
            return $"the twin did a {d.Kind.ToString().ToLowerInvariant()} where the actions have a {e.Kind.ToString().ToLowerInvariant()}";
        }
        if (e.Kind == TwinTraceKind.Output)
        {
            return string.Equals(e.Output, d.Text, StringComparison.OrdinalIgnoreCase) ? null : "the outputs differ";
        }
        var problems = new List<string>();
        if (e.Action is ActionAxes && e.State.Axes is { } axes)
        {
            double worst = (axes - d.Joints).ToArray().Max(Math.Abs);
            if (worst > AngleToleranceDegrees)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"joints differ by up to {worst:0.###} deg"));
            }
        }
        if (e.State.Position is { } position)
        {
            double mm = (position - d.Tcp.Position).Length;
            if (mm > PositionToleranceMm)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"the TCP is {mm:0.###} mm away"));
            }
        }
        if (e.State.Rotation is { } rotation)
        {
            double degrees = RapidGeometry.AngleDegrees(rotation, d.Tcp.Rotation);
            if (degrees > AngleToleranceDegrees)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"the TCP is turned {degrees:0.###} deg away"));
            }
        }
        return problems.Count == 0 ? null : string.Join("; ", problems);
    }

    private static string Describe(Expectation e) => e.Kind == TwinTraceKind.Output
        ? e.Output!
        : $"{(e.State.Axes is { } q ? $"joints {q}, " : "")}TCP {(e.State.Position is { } p ? p.ToString() : "unknown")} {e.State.Rotation?.ToQuaternionString() ?? ""}".TrimEnd();

    private static string Describe(TwinTraceEntry d) => d.Kind == TwinTraceKind.Output
        ? d.Text
        : $"{d.Text}: joints {d.Joints}, TCP {d.Tcp.Position} {d.Tcp.Rotation.ToQuaternionString()}";
}

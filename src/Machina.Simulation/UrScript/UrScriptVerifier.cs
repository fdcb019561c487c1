using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>
/// Runs a compiled URScript program on the twin controller and compares, step by step, the poses the arm reached and the
/// outputs it set with the library's own cursor applying the same actions.
/// </summary>
internal static class UrScriptVerifier
{
    /// <summary>Largest position difference accepted, in mm (scripts carry 1 µm).</summary>
    public const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted, in degrees.</summary>
    public const double AngleToleranceDegrees = 0.01;

    private sealed record Expectation(RobotAction Action, TwinTraceKind Kind, RobotState State, string? Output);

    /// <summary>Runs <paramref name="script"/> on a twin with <paramref name="options"/> and compares it with <paramref name="actions"/>.</summary>
    public static TwinVerification<UrProgramState> Verify(string script, IEnumerable<RobotAction> actions, UrTwinOptions? options = null, CancellationToken cancellation = default)
    {
        options ??= new UrTwinOptions();
        List<Expectation> expected = Expect(actions, options.Model);
        if (StartOf(expected, options) is { } start)
        {
            options = new UrTwinOptions
            {
                Model = options.Model, StartJoints = start, Time = options.Time, RealTime = options.RealTime,
                RandomSeed = options.RandomSeed, SocketOpenTimeout = options.SocketOpenTimeout,
            };
        }
        using var twin = new UrTwinController(options);
        UrProgramState state = twin.Run(script, cancellation);
        List<TwinTraceEntry> done = [.. twin.Arm.Trace.Where(e => e.Kind is TwinTraceKind.Motion or TwinTraceKind.Output)];
        var result = new TwinVerification<UrProgramState> { State = state, Finished = state == UrProgramState.Finished, Error = twin.Error, Seconds = twin.Clock.Seconds };
        int count = Math.Max(expected.Count, done.Count);
        for (int i = 0; i < count; i++)
        {
            Expectation? e = i < expected.Count ? expected[i] : null;
            TwinTraceEntry? d = i < done.Count ? done[i] : null;
            string expectedText = e is null ? "(no more actions)" : Describe(e);
            string actualText = d is null ? "(the program did not get there)" : Describe(d);
            string? problem = (e, d) switch
            {
                (null, _) => "the twin did a step that the actions do not have",
                (_, null) => state == UrProgramState.Finished ? "the program ended before this step" : "the program stopped before this step",
                _ => Compare(e, d),
            };
            result.Steps.Add(new TwinVerifyStep(i + 1, e?.Action.ToInstruction(), d?.Line ?? 0, expectedText, actualText, problem));
        }
        return result;
    }

    /// <summary>
    /// Where the arm starts: at the first motion's target (the cursor knows no pose before its first absolute move, so the path
    /// to it is not the program's to check), in the solution nearest to the options' start joints.
    /// </summary>
    private static Joints? StartOf(List<Expectation> expected, UrTwinOptions options)
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

    private static List<Expectation> Expect(IEnumerable<RobotAction> actions, RobotModel model)
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
                case ActionIODigital io when io.IsDigit && io.PinNumber < (io.IsToolPin ? 2 : 8):
                    expected.Add(new Expectation(action, TwinTraceKind.Output, cursor.Snapshot(),
                        $"{(io.IsToolPin ? UrIoBanks.ToolOut : UrIoBanks.StandardOut)}[{io.PinNumber}] = {(io.On ? "True" : "False")}"));
                    break;
                case ActionIOAnalog io when !io.IsToolPin && io.IsDigit && io.PinNumber < 2 && io.Value is >= 0 and <= 1:
                    expected.Add(new Expectation(action, TwinTraceKind.Output, cursor.Snapshot(),
                        $"{UrIoBanks.AnalogOut}[{io.PinNumber}] = {UrValue.FormatNumber(Math.Round(io.Value, 3))}"));
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
            return e.Output == d.Text ? null : "the outputs differ";
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
            double degrees = UrGeometry.AngleBetween(rotation, d.Tcp.Rotation) * 180 / Math.PI;
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

using System.Globalization;

namespace Machina.Simulation.Twin;

/// <summary>What the library's cursor expects of one step: a motion's pose, or an output's value as the twin's trace writes it.</summary>
/// <param name="Action">The action.</param>
/// <param name="Kind">A motion or an output.</param>
/// <param name="State">The cursor's state after the action.</param>
/// <param name="Output">For an output, its text as the twin's trace writes it (e.g. <c>DO_1 = 1</c>); null for a motion.</param>
internal sealed record TwinExpectation(RobotAction Action, TwinTraceKind Kind, RobotState State, string? Output);

/// <summary>
/// The language-free half of verifying a compiled program on a twin: the cursor's trace of the actions, where the arm
/// starts, and the step-by-step comparison with the twin's trace. Each language's verifier gives its tolerances and how
/// it writes an output (only the outputs its compiler writes are expected).
/// </summary>
/// <param name="PositionToleranceMm">Largest position difference accepted, mm.</param>
/// <param name="AngleToleranceDegrees">Largest orientation or joint difference accepted, degrees.</param>
/// <param name="OutputComparison">How output texts compare (RAPID signal names are case-insensitive).</param>
internal sealed record TwinComparison(double PositionToleranceMm, double AngleToleranceDegrees, StringComparison OutputComparison)
{
    /// <summary>
    /// The expected steps: each motion the cursor accepts, and each output for which <paramref name="outputOf"/> gives the text
    /// the twin will trace (null: the language does not compile that output, so no step is expected).
    /// </summary>
    public static List<TwinExpectation> Expect(IEnumerable<RobotAction> actions, RobotModel model, Func<RobotAction, string?> outputOf)
    {
        var cursor = new RobotCursor { Model = model };
        var expected = new List<TwinExpectation>();
        foreach (RobotAction action in actions)
        {
            if (cursor.TryApply(action) is not null)
            {
                continue;
            }
            if (action is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes or ActionArcMotion)
            {
                expected.Add(new TwinExpectation(action, TwinTraceKind.Motion, cursor.Snapshot(), null));
            }
            else if (action is ActionIODigital or ActionIOAnalog && outputOf(action) is string output)
            {
                expected.Add(new TwinExpectation(action, TwinTraceKind.Output, cursor.Snapshot(), output));
            }
        }
        return expected;
    }

    /// <summary>
    /// Where the arm starts: at the first motion's target (the cursor knows no pose before its first absolute move, so the path
    /// to it is not the program's to check), in the solution nearest to <paramref name="near"/>; null without a motion.
    /// </summary>
    public static Joints? StartOf(List<TwinExpectation> expected, RobotModel model, Joints near)
    {
        TwinExpectation? first = expected.FirstOrDefault(e => e.Kind == TwinTraceKind.Motion);
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
        return model.Kinematics.Closest(new Pose(position, rotation) * tool.Inverse(), near);
    }

    /// <summary>Compares the expected steps with the motions and outputs of the twin's <paramref name="trace"/>, into <paramref name="result"/>.</summary>
    public void Fill<TState>(TwinVerification<TState> result, List<TwinExpectation> expected, IEnumerable<TwinTraceEntry> trace)
        where TState : struct, Enum
    {
        List<TwinTraceEntry> done = [.. trace.Where(e => e.Kind is TwinTraceKind.Motion or TwinTraceKind.Output)];
        int count = Math.Max(expected.Count, done.Count);
        for (int i = 0; i < count; i++)
        {
            TwinExpectation? e = i < expected.Count ? expected[i] : null;
            TwinTraceEntry? d = i < done.Count ? done[i] : null;
            string? problem = (e, d) switch
            {
                (null, _) => "the twin did a step that the actions do not have",
                (_, null) => result.Finished ? "the program ended before this step" : "the program stopped before this step",
                (_, { } step) => Compare(e, step),
            };
            result.Steps.Add(new TwinVerifyStep(i + 1, e?.Action.ToInstruction(), d?.Line ?? 0, e is null ? "(no more actions)" : Describe(e),
                d is { } did ? Describe(did) : "(the program did not get there)", problem, e?.Action, d is not null));
        }
    }

    private string? Compare(TwinExpectation e, TwinTraceEntry d)
    {
        if (e.Kind != d.Kind)
        {
            return $"the twin did a {d.Kind.ToString().ToLowerInvariant()} where the actions have a {e.Kind.ToString().ToLowerInvariant()}";
        }
        if (e.Kind == TwinTraceKind.Output)
        {
            return string.Equals(e.Output, d.Text, OutputComparison) ? null : "the outputs differ";
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
            double degrees = TwinRotation.AngleDegrees(rotation, d.Tcp.Rotation);
            if (degrees > AngleToleranceDegrees)
            {
                problems.Add(string.Create(CultureInfo.InvariantCulture, $"the TCP is turned {degrees:0.###} deg away"));
            }
        }
        return problems.Count == 0 ? null : string.Join("; ", problems);
    }

    private static string Describe(TwinExpectation e) => e.Kind == TwinTraceKind.Output
        ? e.Output!
        : $"{(e.State.Axes is { } q ? $"joints {q}, " : "")}TCP {(e.State.Position is { } p ? p.ToString() : "unknown")} {e.State.Rotation?.ToQuaternionString() ?? ""}".TrimEnd();

    private static string Describe(TwinTraceEntry d) => d.Kind == TwinTraceKind.Output
        ? d.Text
        : $"{d.Text}: joints {d.Joints}, TCP {d.Tcp.Position} {d.Tcp.Rotation.ToQuaternionString()}";
}

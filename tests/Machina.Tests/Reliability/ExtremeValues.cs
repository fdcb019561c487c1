using System.Reflection;

namespace Machina.Tests.Reliability;

/// <summary>
/// The edges of every parameter type of <see cref="Robot"/>'s verbs, and the verbs themselves, found by reflection: every public
/// instance method that issues actions. A new verb is covered as soon as it exists; a new parameter type needs its edges here.
/// </summary>
internal static class ExtremeValues
{
    /// <summary>Public methods of <see cref="Robot"/> that return bool but issue no action.</summary>
    private static readonly HashSet<string> NotVerbs =
    [
        nameof(Robot.IsBrand), nameof(Robot.ControlMode), nameof(Robot.ConnectionManager), nameof(Robot.Connect),
        nameof(Robot.Disconnect), nameof(Robot.WaitForCompletion), nameof(Robot.SaveProgram), nameof(Robot.StreamConfiguration), nameof(Robot.Resume), nameof(Robot.SetUser),
        nameof(Robot.Stop), nameof(Robot.Pause), // online controls of the controller, not actions
    ];

    /// <summary>A million characters: longer than any line a controller takes.</summary>
    internal static readonly string Huge = new('x', 1_000_000);

    /// <summary>Texts at the edges: empty, null, huge, control characters, quotes and escapes, non-ASCII, blank.</summary>
    internal static readonly string?[] Texts =
    [
        "", null, Huge, "a\0b\r\nc\td\u001b[0m\u0085e\u2028f\u007f", "\"q\" 'a' \\\" ; , ) ( // ! # { }", "Grüße 日本 🤖 \ud800",
        " ", "\"",
    ];

    /// <summary>Numbers at the edges: signed zeros, denormals, the largest finite values, infinities and NaN.</summary>
    internal static readonly double[] Doubles =
    [
        0.0, -0.0, double.Epsilon, -double.Epsilon, 1e308, -1e308, double.MaxValue, double.PositiveInfinity, double.NegativeInfinity, double.NaN,
    ];

    internal static readonly int[] Ints = [0, -1, int.MinValue, int.MaxValue, 4096, 1 << 24];

    internal static readonly long[] Longs = [0, -1, long.MinValue, long.MaxValue, int.MaxValue + 1L];

    /// <summary>The verbs: public instance methods of <see cref="Robot"/> returning bool, except the few that issue nothing.</summary>
    internal static IReadOnlyList<MethodInfo> Verbs() =>
    [
        .. typeof(Robot).GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.DeclaredOnly)
            .Where(m => !m.IsSpecialName && m.ReturnType == typeof(bool) && !NotVerbs.Contains(m.Name))
            .OrderBy(Describe, StringComparer.Ordinal),
    ];

    /// <summary><c>Name(type name, …)</c>.</summary>
    internal static string Describe(MethodInfo m) =>
        $"{m.Name}({string.Join(", ", m.GetParameters().Select(p => $"{p.ParameterType.Name} {p.Name}"))})";

    /// <summary>The edge values of a parameter type, or null when this file has none (the test then fails and says which).</summary>
    internal static IReadOnlyList<object?>? Edges(Type type)
    {
        if (type == typeof(double)) { return [.. Doubles.Cast<object?>()]; }
        if (type == typeof(int)) { return [.. Ints.Cast<object?>()]; }
        if (type == typeof(long)) { return [.. Longs.Cast<object?>()]; }
        if (type == typeof(bool)) { return [true, false]; }
        if (type == typeof(string)) { return Texts; }
        if (type.IsEnum) { return [.. Enum.GetValues(type).Cast<object?>(), Enum.ToObject(type, -1), Enum.ToObject(type, int.MaxValue)]; }
        if (type == typeof(Vector)) { return [.. Doubles.SelectMany(d => new object?[] { new Vector(d, 0, 0), new Vector(d, d, d) })]; }
        if (type == typeof(Joints)) { return [.. Doubles.SelectMany(d => new object?[] { new Joints(0, d, 0, 0, 0, 0), new Joints(d, d, d, d, d, d) })]; }
        if (type == typeof(Rotation)) { return [default(Rotation), Rotation.FromQuaternion(1e308, 1e-308, 0, 0), Rotation.FromAxisAngle(Vector.ZAxis, 1e308), Rotation.FromQuaternion(double.Epsilon, 0, 0, 1)]; }
        if (type == typeof(Orientation)) { return [default(Orientation), new Orientation(Rotation.FromAxisAngle(Vector.XAxis, -1e308))]; }
        if (type == typeof(Plane)) { return [.. Doubles.Select(d => (object?)new Plane(new Vector(d, d, d), Rotation.Identity)), default(Plane)]; }
        if (type == typeof(Tool)) { return [null, .. Doubles.Where(double.IsFinite).Select(d => (object?)Tool.Create("T", new Vector(d, 0, d), Rotation.Identity, 1, new Vector(0, 0, d)))]; }
        if (type == typeof(RobotAction)) { return [null, new ActionMessage(Huge), new ActionSpeed(double.Epsilon, false), new ActionTranslation(new Vector(1e308, -1e308, 0), true)]; }
        return null;
    }

    /// <summary>A valid value for a parameter, so that one parameter at a time can be set to an edge.</summary>
    internal static object? Good(ParameterInfo p) => p.ParameterType switch
    {
        Type t when t == typeof(double) => AxisComponent(p.Name!) ?? ArcPoint(p.Name!, p.Member.Name.EndsWith("To", StringComparison.Ordinal)) ?? 1.0,
        Type t when t == typeof(int) => 1,
        Type t when t == typeof(long) => 1L,
        Type t when t == typeof(bool) => false,
        Type t when t == typeof(Vector) => (p.Name, p.Member.Name.EndsWith("To", StringComparison.Ordinal)) switch
        {
            ("through", false) => new Vector(10, 10, 0),
            ("end", false) => new Vector(20, 0, 0),
            ("through", true) => new Vector(350, 50, 400),
            ("end", true) => new Vector(400, 0, 400),
            ("yAxis", _) => new Vector(0, 1, 0),
            _ => new Vector(1, 0, 0),
        },
        Type t when t == typeof(Rotation) => Rotation.Identity,
        Type t when t == typeof(Orientation) => new Orientation(Rotation.Identity),
        Type t when t == typeof(Joints) => new Joints(0, 0, 0, 0, 90, 0),
        Type t when t == typeof(Plane) => new Plane(p.Name == "through" ? new Vector(350, 50, 400) : new Vector(400, 0, 400), Rotation.FlippedAroundY),
        Type t when t == typeof(Tool) => Tool.Create("T", new Vector(0, 0, 100), Rotation.Identity),
        Type t when t == typeof(RobotAction) => new ActionWait(1),
        Type t when t.IsEnum => Enum.GetValues(t).GetValue(0),
        Type t when t == typeof(string) => p.Name switch
        {
            "target" => "All",
            "devicePart" => "extruder",
            "motionType" => "linear",
            "referenceCS" => "world",
            "toolName" => "T",
            "instructions" => "Wait(1);",
            "pinId" => "1",
            _ => "Bot",
        },
        _ => null,
    };

    /// <summary>Arc points given as numbers, near the starting pose so that with it they make a short circle: relative, through (10, 10, 0) and
    /// end (20, 0, 0); absolute, through (350, 50, 400) and end (400, 0, 400).</summary>
    private static double? ArcPoint(string name, bool absolute) => name switch
    {
        "throughX" => absolute ? 350 : 10,
        "throughY" => absolute ? 50 : 10,
        "endX" => absolute ? 400 : 20,
        "throughZ" or "endZ" => absolute ? 400 : 0,
        "endY" => 0,
        _ => null,
    };

    /// <summary>Frame axes given as numbers get the world X and Y axes (all ones would be parallel, an error of their own).</summary>
    private static double? AxisComponent(string name) => name switch
    {
        _ when name.Contains("XAxis", StringComparison.Ordinal) || name.Contains("_vX", StringComparison.Ordinal) || name is "x0" or "x1" or "x2" =>
            name.EndsWith('X') || name.EndsWith('0') ? 1 : 0,
        _ when name.Contains("YAxis", StringComparison.Ordinal) || name.Contains("_vY", StringComparison.Ordinal) || name is "y0" or "y1" or "y2" =>
            name.EndsWith('Y') || name.EndsWith('1') ? 1 : 0,
        _ => null,
    };

    /// <summary>
    /// Cases for property tests: each verb with good values, then each parameter set to each of its edges (texts up to 1,000
    /// characters), then <paramref name="seeded"/> random mixtures from <paramref name="seed"/>.
    /// </summary>
    internal static List<(string Name, MethodInfo Verb, object?[] Args)> Cases(int seed, int seeded)
    {
        var cases = new List<(string Name, MethodInfo Verb, object?[] Args)>();
        IReadOnlyList<MethodInfo> verbs = ExtremeValues.Verbs();
        foreach (MethodInfo verb in verbs)
        {
            ParameterInfo[] ps = verb.GetParameters();
            object?[] good = [.. ps.Select(ExtremeValues.Good)];
            cases.Add(($"{ExtremeValues.Describe(verb)} with good values", verb, good));
            for (int i = 0; i < ps.Length; i++)
            {
                foreach (object? edge in ExtremeValues.Edges(ps[i].ParameterType)!.Where(e => e is not string { Length: > 1000 }))
                {
                    object?[] args = (object?[])good.Clone();
                    args[i] = edge;
                    cases.Add(($"{ExtremeValues.Describe(verb)} with {ps[i].Name} = {edge}", verb, args));
                }
            }
        }
        var random = new Random(seed);
        for (int n = 0; n < seeded; n++)
        {
            MethodInfo verb = verbs[random.Next(verbs.Count)];
            object?[] args = [.. verb.GetParameters().Select(p =>
            {
                object?[] choices = [ExtremeValues.Good(p), .. ExtremeValues.Edges(p.ParameterType)!.Where(e => e is not string { Length: > 1000 })];
                return choices[random.Next(choices.Length)];
            })];
            cases.Add(($"seeded {n}: {ExtremeValues.Describe(verb)}", verb, args));
        }
        return cases;
    }
}

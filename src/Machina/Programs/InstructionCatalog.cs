namespace Machina;

/// <summary>
/// Every instruction name the parser understands, with how many arguments it takes and the action it makes. This is the
/// original's parseable API plus the instructions it wrote but could not read back (ArcMotion, ArmAngle, CustomCode,
/// Coordinates, Comment, 3-argument ExternalAxis, Transform, temperatures and extrusion).
/// </summary>
internal static class InstructionCatalog
{
    internal sealed record Overload(int MinArgs, int MaxArgs, string Usage, Func<InstructionArgs, RobotAction> Create);

    private static readonly Dictionary<string, Overload[]> Table = Build();

    private static readonly Dictionary<string, string> ProperNames =
        Table.Keys.ToDictionary(k => k, k => k, StringComparer.OrdinalIgnoreCase);

#if NET9_0_OR_GREATER
    private static readonly Dictionary<string, Overload[]>.AlternateLookup<ReadOnlySpan<char>> BySpan = Table.GetAlternateLookup<ReadOnlySpan<char>>();
#endif

    /// <summary>The overloads of an exact (case-sensitive) name, or null.</summary>
    internal static Overload[]? Find(string name) => Table.GetValueOrDefault(name);

    /// <summary>The overloads of an exact (case-sensitive) name read from text, with the name as a string, without allocating; false when unknown.</summary>
    internal static bool TryFind(ReadOnlySpan<char> name, out string key, out Overload[] overloads)
    {
#if NET9_0_OR_GREATER
        bool found = BySpan.TryGetValue(name, out string? actual, out Overload[]? value);
#else
        // .NET 8 has no span lookup: the name is allocated (only the .NET 10 build parses without allocating).
        string actual = name.ToString();
        bool found = Table.TryGetValue(actual, out Overload[]? value);
#endif
        key = found ? actual! : "";
        overloads = value ?? [];
        return found;
    }

    /// <summary>The properly spelled name when <paramref name="name"/> differs only in letter case, or null.</summary>
    internal static string? ProperName(string name) => ProperNames.GetValueOrDefault(name);

    /// <summary>All instruction names.</summary>
    internal static IEnumerable<string> Names => Table.Keys;

    private static Dictionary<string, Overload[]> Build()
    {
        var t = new Dictionary<string, List<Overload>>(StringComparer.Ordinal);
        void Add(string name, int min, int max, string usage, Func<InstructionArgs, RobotAction> create)
        {
            if (!t.TryGetValue(name, out var list))
            {
                t[name] = list = [];
            }
            list.Add(new Overload(min, max, usage, create));
        }

        Add("Speed", 1, 1, "Speed(increment)", a => new ActionSpeed(a.D(0), true));
        Add("SpeedTo", 1, 1, "SpeedTo(mmPerSecond)", a => new ActionSpeed(a.D(0), false));
        Add("Acceleration", 1, 1, "Acceleration(increment)", a => new ActionAcceleration(a.D(0), true));
        Add("AccelerationTo", 1, 1, "AccelerationTo(mmPerSecondSquared)", a => new ActionAcceleration(a.D(0), false));
        Add("Precision", 1, 1, "Precision(increment)", a => new ActionPrecision(a.D(0), true));
        Add("PrecisionTo", 1, 1, "PrecisionTo(radius)", a => new ActionPrecision(a.D(0), false));
        Add("MotionMode", 1, 1, "MotionMode(\"linear\"|\"joint\")", a => new ActionMotionMode(a.E<MotionType>(0, "motion type")));
        Add("Coordinates", 1, 1, "Coordinates(\"world\"|\"local\")", a => new ActionCoordinates(a.E<ReferenceCS>(0, "coordinate system")));
        Add("PushSettings", 0, 0, "PushSettings()", _ => new ActionPushPop(true));
        Add("PopSettings", 0, 0, "PopSettings()", _ => new ActionPushPop(false));
        Add("Move", 2, 3, "Move(x, y[, z])", a => new ActionTranslation(new Vector(a.D(0), a.D(1), a.Count > 2 ? a.D(2) : 0), true));
        Add("MoveTo", 3, 3, "MoveTo(x, y, z)", a => new ActionTranslation(new Vector(a.D(0), a.D(1), a.D(2)), false));
        Add("Rotate", 4, 4, "Rotate(axisX, axisY, axisZ, degrees)", a => new ActionRotation(new Vector(a.D(0), a.D(1), a.D(2)), a.D(3), true));
        Add("RotateTo", 6, 6, "RotateTo(xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ)", a => new ActionRotation(Axes(a, 0), false));
        Add("Transform", 7, 8, "Transform(x, y, z, axisX, axisY, axisZ, degrees[, translationFirst])", a => new ActionTransformation(
            new Vector(a.D(0), a.D(1), a.D(2)), new ActionRotation(new Vector(a.D(3), a.D(4), a.D(5)), a.D(6), true).Rotation, true, a.B(7, true)));
        Add("TransformTo", 9, 9, "TransformTo(x, y, z, xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ)", a => new ActionTransformation(
            new Vector(a.D(0), a.D(1), a.D(2)), Axes(a, 3), false, true));
        Add("ArcMotion", 6, 6, "ArcMotion(throughX, throughY, throughZ, endX, endY, endZ)", a => Arc(a, true));
        Add("ArcMotionTo", 6, 6, "ArcMotionTo(throughX, throughY, throughZ, endX, endY, endZ)", a => Arc(a, false));
        Add("ArcMotionTo", 18, 18, "ArcMotionTo(through origin, X axis, Y axis, end origin, X axis, Y axis: 18 numbers)", a => new ActionArcMotion(
            new Plane(new Vector(a.D(0), a.D(1), a.D(2)), Axes(a, 3)), new Plane(new Vector(a.D(9), a.D(10), a.D(11)), Axes(a, 12)), false, false));
        Add("Axes", 6, 6, "Axes(j1, j2, j3, j4, j5, j6)", a => new ActionAxes(Joints6(a), true));
        Add("AxesTo", 6, 6, "AxesTo(j1, j2, j3, j4, j5, j6)", a => new ActionAxes(Joints6(a), false));
        Add("ExternalAxis", 2, 3, "ExternalAxis(axisNumber, increment[, \"all\"|\"cartesian\"|\"joint\"])", a => ExternalAxis(a, true));
        Add("ExternalAxisTo", 2, 3, "ExternalAxisTo(axisNumber, value[, \"all\"|\"cartesian\"|\"joint\"])", a => ExternalAxis(a, false));
        Add("ArmAngle", 1, 1, "ArmAngle(increment)", a => new ActionArmAngle(a.D(0), true));
        Add("ArmAngleTo", 1, 1, "ArmAngleTo(degrees)", a => new ActionArmAngle(a.D(0), false));
        Add("Wait", 1, 1, "Wait(milliseconds)", a => new ActionWait(a.L(0)));
        Add("Message", 0, 1, "Message(\"text\")", a => new ActionMessage(a.Count > 0 ? a.S(0) : ""));
        Add("Comment", 0, 1, "Comment(\"text\")", a => new ActionComment(a.Count > 0 ? a.S(0) : ""));
        Add("CustomCode", 1, 2, "CustomCode(\"statement\"[, isDeclaration])", a => new ActionCustomCode(a.S(0), a.B(1, false)));
        Add("DefineTool", 14, 14, "DefineTool(\"name\", tipX, tipY, tipZ, xAxisX, xAxisY, xAxisZ, yAxisX, yAxisY, yAxisZ, weightKg, cogX, cogY, cogZ)", a => new ActionDefineTool(
            Tool.Create(a.S(0), a.D(1), a.D(2), a.D(3), a.D(4), a.D(5), a.D(6), a.D(7), a.D(8), a.D(9), a.D(10), a.D(11), a.D(12), a.D(13))));
        Add("AttachTool", 1, 1, "AttachTool(\"name\")", a => new ActionAttachTool(a.S(0)));
        Add("DetachTool", 0, 0, "DetachTool()", _ => new ActionDetachTool());
        Add("WriteDigital", 2, 3, "WriteDigital(pin, on[, toolPin])", a => new ActionIODigital(a.S(0), a.B(1, false), a.B(2, false)));
        Add("WaitForDigital", 2, 4, "WaitForDigital(pin, on[, timeoutMillis[, toolPin]])", a => new ActionWaitDigital(a.S(0), a.B(1, false), a.Count > 2 ? a.L(2) : 0, a.B(3, false)));
        Add("ReadDigital", 1, 2, "ReadDigital(pin[, toolPin])", a => new ActionReadInput(a.S(0), false, a.B(1, false)));
        Add("ReadAnalog", 1, 2, "ReadAnalog(pin[, toolPin])", a => new ActionReadInput(a.S(0), true, a.B(1, false)));
        Add("WriteAnalog", 2, 3, "WriteAnalog(pin, value[, toolPin])", a => new ActionIOAnalog(a.S(0), a.D(1), a.B(2, false)));
        Add("Temperature", 2, 3, "Temperature(increment, \"extruder\"|\"bed\"|\"chamber\"[, wait])", a => Temperature(a, true));
        Add("TemperatureTo", 2, 3, "TemperatureTo(celsius, \"extruder\"|\"bed\"|\"chamber\"[, wait])", a => Temperature(a, false));
        Add("ExtrusionRate", 1, 1, "ExtrusionRate(increment)", a => new ActionExtrusionRate(a.D(0), true));
        Add("ExtrusionRateTo", 1, 1, "ExtrusionRateTo(mmPerMm)", a => new ActionExtrusionRate(a.D(0), false));
        Add("Extrude", 0, 1, "Extrude([on])", a => new ActionExtrusion(a.B(0, true)));
        Add("Initialize", 0, 0, "Initialize()", _ => new ActionInitialization(true));
        Add("Terminate", 0, 0, "Terminate()", _ => new ActionInitialization(false));
        return t.ToDictionary(kv => kv.Key, kv => kv.Value.ToArray(), StringComparer.Ordinal);
    }

    private static Rotation Axes(InstructionArgs a, int first) =>
        Rotation.FromAxes(new Vector(a.D(first), a.D(first + 1), a.D(first + 2)), new Vector(a.D(first + 3), a.D(first + 4), a.D(first + 5)));

    private static Joints Joints6(InstructionArgs a) => new(a.D(0), a.D(1), a.D(2), a.D(3), a.D(4), a.D(5));

    private static ActionArcMotion Arc(InstructionArgs a, bool relative) => new(
        new Plane(new Vector(a.D(0), a.D(1), a.D(2)), Rotation.Identity), new Plane(new Vector(a.D(3), a.D(4), a.D(5)), Rotation.Identity), relative, true);

    private static ActionExternalAxis ExternalAxis(InstructionArgs a, bool relative) => new(
        a.I(0), a.D(1), a.Count > 2 ? a.E<ExternalAxesTarget>(2, "external axes target") : ExternalAxesTarget.All, relative);

    private static ActionTemperature Temperature(InstructionArgs a, bool relative) =>
        new(a.D(0), a.E<RobotPartType>(1, "printer part"), a.B(2, true), relative);
}

using System.Runtime.CompilerServices;
namespace Machina;

/// <summary>
/// What a RAPID module must declare before <c>PROC main()</c>, gathered in a first pass over the actions: the speeds and zones
/// that motions use, the tools that motions use, custom declarations, and whether IO signals are set. Names are unique
/// (speeds and zones are keyed by the rounded value that is written, so two speeds that print the same share one name).
/// </summary>
internal sealed class RapidPlan
{
    private static readonly int[] PredefinedZones = [1, 5, 10, 15, 20, 30, 40, 50, 60, 80, 100, 150, 200];

    private readonly Dictionary<double, string> _speedNames = [];
    private readonly Dictionary<double, string> _zoneNames = [];
    private readonly Dictionary<Tool, string> _toolNames = [];
    private readonly List<double> _speeds = [];
    private readonly List<double> _zones = [];
    private readonly List<Tool> _tools = [];
    private double _lastSpeed = double.NaN, _lastZone = double.NaN;
    private string _lastSpeedName = "", _lastZoneName = "", _lastToolName = "";
    private Tool? _lastTool;

    /// <summary>The smallest speed written, mm/s: speeds are written with 3 decimals, and a speeddata of 0 cannot move.</summary>
    internal const double MinSpeed = 0.001;

    /// <summary>A speed as written in speeddata: rounded to 3 decimals, at least <see cref="MinSpeed"/>.</summary>
    private static double SpeedKey(double speed) => Math.Max(Math.Round(speed, 3), MinSpeed);

    /// <summary>Identifiers in use in the module.</summary>
    internal RapidNames Names { get; } = new();

    /// <summary>Module name: the program name made a valid RAPID identifier.</summary>
    internal string ModuleName { get; private set; } = "";

    /// <summary>Custom declaration statements, in order.</summary>
    internal List<string> CustomDeclarations { get; } = [];

    /// <summary>True when the program sets IO signals.</summary>
    internal bool UsesIO { get; private set; }

    /// <summary>True when the program reads a digital input (into machina_di).</summary>
    internal bool ReadsDigital { get; private set; }

    /// <summary>True when the program reads an analog input (into machina_ai).</summary>
    internal bool ReadsAnalog { get; private set; }

    /// <summary>Declaration lines for speeds, zones and tools.</summary>
    internal List<string> DataLines { get; } = [];

    /// <summary>Runs the first pass: replays the actions (refused ones are skipped; the writing pass reports them).</summary>
    internal static RapidPlan Collect(CompileJob job)
    {
        RapidPlan plan = Start(job, live: false);
        foreach ((RobotAction action, RobotCursor cursor) in job.Applied())
        {
            plan.Observe(action, cursor);
        }
        plan.Finish();
        return plan;
    }

    /// <summary>
    /// Text that every statement which adds to the declarations, or changes the speed, zone or tool that motions use, contains
    /// (instruction names are case-sensitive): <c>Speed</c>/<c>SpeedTo</c>, <c>Precision</c>/<c>PrecisionTo</c>,
    /// <c>PopSettings</c>, <c>DefineTool</c>/<c>AttachTool</c>/<c>DetachTool</c>, <c>CustomCode</c>, and the IO statements.
    /// A text that names none of them but <c>SpeedTo(number)</c> declares what <see cref="Foresee"/> says, if it moves after each.
    /// </summary>
    internal static readonly string[] WordsThatDeclare = ["Speed", "Precision", "Settings", "Tool", "CustomCode", "Digital", "Analog"];

    /// <summary>
    /// The plan of a program whose only statements that declare are the <c>SpeedTo</c>s <paramref name="scan"/> found, each
    /// followed by a motion: the start state's zone and tool, and the start speed (if <see cref="RapidSpeedScan.StartSpeedMoves"/>)
    /// then each speed set, in order. Finished.
    /// </summary>
    internal static RapidPlan Foresee(CompileJob job, RapidSpeedScan scan)
    {
        RapidPlan plan = Start(job, live: false);
        RobotCursor start = job.NewCursor();
        if (scan.StartSpeedMoves)
        {
            plan.ObserveMotion(start);
        }
        foreach (double speed in scan.Speeds)
        {
            AddOnce(plan._speeds, plan._speedNames, SpeedKey(speed), ref plan._lastSpeedSeen);
        }
        AddOnce(plan._zones, plan._zoneNames, Math.Round(start.Precision, 3), ref plan._lastZoneSeen); // the tool is Start's
        plan.Finish();
        return plan;
    }

    /// <summary>True when this finished plan writes the same text before <c>PROC main()</c> as <paramref name="other"/>.</summary>
    internal bool DeclaresAs(RapidPlan other) =>
        ModuleName == other.ModuleName && UsesIO == other.UsesIO && ReadsDigital == other.ReadsDigital && ReadsAnalog == other.ReadsAnalog
        && DataLines.SequenceEqual(other.DataLines) && CustomDeclarations.SequenceEqual(other.CustomDeclarations);

    /// <summary>
    /// A plan that is gathered while the instructions are written, in one pass (<see cref="Observe"/> before each action is
    /// written). Until <see cref="Finish"/> it answers names provisionally, claimed in the order the instructions meet them;
    /// <see cref="Finish"/> names everything as <see cref="Collect"/> does and <see cref="ProvisionalNamesHeld"/> tells whether
    /// every answer given was the final name (it is not only when names collide, e.g. a tool called <c>vel100</c>).
    /// </summary>
    internal static RapidPlan StartLive(CompileJob job) => Start(job, live: true);

    private static RapidPlan Start(CompileJob job, bool live)
    {
        var plan = new RapidPlan();
        plan.ModuleName = plan.Names.Claim(RapidNames.LooksLikeTarget(job.ProgramName) ? "M_" + job.ProgramName : job.ProgramName, "M");
        if (live)
        {
            plan._provisional = new RapidNames();
            plan._provisional.Claim(plan.ModuleName, "M");
        }
        if (job.NewCursor().Tool is Tool startTool)
        {
            plan.AddTool(startTool);
        }
        return plan;
    }

    // One-pass mode: names claimed as the instructions meet them, and every answer given, checked by Finish.
    private RapidNames? _provisional;
    private readonly Dictionary<double, string> _provisionalSpeeds = [];
    private readonly Dictionary<double, string> _provisionalZones = [];
    private readonly Dictionary<Tool, string> _provisionalTools = [];

    /// <summary>True while names are answered provisionally (one-pass mode, before <see cref="Finish"/>).</summary>
    internal bool IsLive => _provisional is not null;

    /// <summary>After <see cref="Finish"/> in one-pass mode: true when every provisional answer is the final name.</summary>
    internal bool ProvisionalNamesHeld { get; private set; } = true;

    private string ProvisionalSpeed(double key) => Provisional(_provisionalSpeeds, key, SpeedIdentifier);

    private string ProvisionalZone(double key) => Provisional(_provisionalZones, key, static (zone, names) => ZoneName(zone, names, out _));

    private string ProvisionalTool(Tool tool) => Provisional(_provisionalTools, tool, ToolIdentifier);

    /// <summary>The name already answered for <paramref name="key"/>, or a new one claimed among the provisional names.</summary>
    private string Provisional<TKey>(Dictionary<TKey, string> answered, TKey key, Func<TKey, RapidNames, string> claim) where TKey : notnull
    {
        if (!answered.TryGetValue(key, out string? name))
        {
            answered[key] = name = claim(key, _provisional!);
        }
        return name;
    }

    private static string SpeedIdentifier(double speed, RapidNames names) => names.Claim("vel" + NameNumber(speed), "vel");

    private static string ToolIdentifier(Tool tool, RapidNames names) =>
        names.Claim(RapidNames.LooksLikeTarget(tool.Name) ? "tool_" + tool.Name : tool.Name, "tool_");

    /// <summary>Records what <paramref name="action"/> adds to the declarations, with the cursor state after it.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal void Observe(RobotAction action, RobotCursor cursor)
    {
        switch (action)
        {
            case ActionTranslation or ActionRotation or ActionTransformation or ActionAxes or ActionArcMotion:
                ObserveMotion(cursor);
                break;
            case ActionCustomCode { IsDeclaration: true } code:
                CustomDeclarations.Add(code.Statement);
                break;
            case ActionIODigital or ActionIOAnalog:
                UsesIO = true;
                break;
            case ActionReadInput read:
                UsesIO = true;
                ReadsDigital |= !read.IsAnalog;
                ReadsAnalog |= read.IsAnalog;
                break;
        }
    }

    /// <summary>Records the speed, zone and tool of a motion that leaves the cursor in <paramref name="cursor"/>'s state.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private void ObserveMotion(RobotCursor cursor)
    {
        AddOnce(_speeds, _speedNames, SpeedKey(cursor.Speed), ref _lastSpeedSeen);
        AddOnce(_zones, _zoneNames, Math.Round(cursor.Precision, 3), ref _lastZoneSeen);
        if (cursor.Tool is Tool tool)
        {
            AddTool(tool);
        }
    }

    private void AddTool(Tool tool)
    {
        if (!_toolNames.ContainsKey(tool))
        {
            _toolNames[tool] = "";
            _tools.Add(tool);
        }
    }

    // The value each motion met last: most motions use the speed and zone of the one before, and skip the dictionary.
    private double _lastSpeedSeen = double.NaN, _lastZoneSeen = double.NaN;

    /// <summary>Adds <paramref name="value"/> to <paramref name="values"/> the first time it is met (the order of first use).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // twice a motion: it ran unoptimised until the runtime tiered it up
    private static void AddOnce(List<double> values, Dictionary<double, string> seen, double value, ref double last)
    {
        if (value != last)
        {
            last = value;
            if (seen.TryAdd(value, ""))
            {
                values.Add(value);
            }
        }
    }

    /// <summary>A number for a generated name: fixed-point, up to 3 decimals, '.' as '_' (100 → "100", 2.5 → "2_5").</summary>
    private static string NameNumber(double value) => value.ToString("0.###", Num.Inv).Replace('.', '_');

    /// <summary>Names every speed, zone and tool and makes their declaration lines (and checks the provisional answers).</summary>
    internal void Finish()
    {
        foreach (double zone in _zones)
        {
            _zoneNames[zone] = ZoneName(zone, Names, out bool predefined);
            if (!predefined)
            {
                DataLines.Add($"  CONST zonedata {_zoneNames[zone]} := {RapidText.ZoneData(zone)};");
            }
        }
        var speedLines = new List<string>(_speeds.Count);
        foreach (double speed in _speeds)
        {
            string name = SpeedIdentifier(speed, Names);
            _speedNames[speed] = name;
            speedLines.Add($"  CONST speeddata {name} := {RapidText.SpeedData(speed)};");
        }
        var toolLines = new List<string>(_tools.Count);
        foreach (Tool tool in _tools)
        {
            string name = ToolIdentifier(tool, Names);
            _toolNames[tool] = name;
            toolLines.Add($"  PERS tooldata {name} := {RapidText.ToolData(tool)};");
        }
        DataLines.InsertRange(0, speedLines);
        DataLines.InsertRange(0, toolLines);
        if (_provisional is not null)
        {
            ProvisionalNamesHeld = Held(_provisionalSpeeds, _speedNames) && Held(_provisionalZones, _zoneNames) && Held(_provisionalTools, _toolNames);
            _provisional = null;
            _lastSpeed = _lastZone = double.NaN;
            _lastTool = null;
        }
    }

    private static bool Held<TKey>(Dictionary<TKey, string> answered, Dictionary<TKey, string> final) where TKey : notnull
    {
        foreach (KeyValuePair<TKey, string> pair in answered)
        {
            if (!final.TryGetValue(pair.Key, out string? name) || name != pair.Value)
            {
                return false;
            }
        }
        return true;
    }

    private static string ZoneName(double zone, RapidNames names, out bool predefined)
    {
        predefined = true;
        if (zone < 0.001)
        {
            return "fine";
        }
        if (Math.Abs(zone - Math.Round(zone)) < 0.001 && Array.IndexOf(PredefinedZones, (int)Math.Round(zone)) >= 0)
        {
            return "z" + Num.I((long)Math.Round(zone));
        }
        predefined = false;
        return names.Claim("zone" + NameNumber(zone), "zone");
    }

    /// <summary>The speeddata name for the cursor's speed.</summary>
    // Inlined into the optimised writer (a method marked AggressiveOptimization is never inlined: it was one call a motion).
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    internal string SpeedName(double speed)
    {
        double key = SpeedKey(speed);
        if (key != _lastSpeed)
        {
            _lastSpeed = key;
            _lastSpeedName = IsLive ? ProvisionalSpeed(key) : _speedNames[key];
        }
        return _lastSpeedName;
    }

    /// <summary>The zonedata name for the cursor's precision (<c>fine</c> for 0).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // once a motion, as SpeedName
    internal string ZoneName(double precision)
    {
        double key = Math.Round(precision, 3);
        if (key != _lastZone)
        {
            _lastZone = key;
            _lastZoneName = IsLive ? ProvisionalZone(key) : _zoneNames[key];
        }
        return _lastZoneName;
    }

    /// <summary>The tooldata name for the tool in use (<c>Tool0</c>, the flange, when none).</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)] // once a motion, as SpeedName
    internal string ToolName(Tool? tool)
    {
        if (tool is null)
        {
            return "Tool0";
        }
        if (!ReferenceEquals(tool, _lastTool))
        {
            _lastTool = tool;
            _lastToolName = IsLive ? ProvisionalTool(tool) : _toolNames[tool];
        }
        return _lastToolName;
    }

    /// <summary>The declared name of a tool, or null when no motion uses it (it is then not declared).</summary>
    /// <remarks>In one-pass mode a tool not yet used by a motion is answered as if it will be; <see cref="Finish"/> checks it.</remarks>
    internal string? DeclaredToolName(Tool tool) =>
        IsLive ? ProvisionalTool(tool) : _toolNames.TryGetValue(tool, out string? name) ? name : null;
}

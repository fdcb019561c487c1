using System.Collections.Frozen;

namespace Machina.Simulation.UrScript;

/// <summary>
/// The built-in functions the twin knows, with the parameter names and defaults of UR's Script Manual. A program that calls
/// anything else is refused at compile time.
/// </summary>
internal static partial class UrBuiltins
{
    /// <summary>Default of a parameter whose value depends on the controller (the current joints, the active TCP, …).</summary>
    private static readonly object NotGiven = UrNone.Value;

    /// <summary>Every built-in by name.</summary>
    public static FrozenDictionary<string, UrBuiltin> All { get; } = Build();

    private static FrozenDictionary<string, UrBuiltin> Build()
    {
        var table = new Dictionary<string, UrBuiltin>(StringComparer.Ordinal);
        AddMotion(table);
        AddSpeed(table);
        AddPoseMath(table);
        AddIo(table);
        AddSockets(table);
        AddMath(table);
        AddMisc(table);
        AddControl(table);
        AddOptimove(table);
        AddRtdeControl(table);
        return table.ToFrozenDictionary(StringComparer.Ordinal);
    }

    private static void Add(Dictionary<string, UrBuiltin> table, string name, Func<UrMachine, int, object[], object> body, params (string, object?)[] parameters) =>
        table.Add(name, new UrBuiltin(name, parameters, body));

    /// <summary>A required parameter.</summary>
    private static (string, object?) R(string name) => (name, null);

    /// <summary>An optional parameter with its default.</summary>
    private static (string, object?) O(string name, object value) => (name, value);

    // The argument readers take the value as it is when it has the right type; only a wrong one names the argument (the words
    // of the runtime error are built then, not for every call: a streamed move read about fifteen arguments).

    private static double Num(object[] a, int i, int line, string function, string parameter) => a[i] switch
    {
        double d => d,
        int n => n,
        var other => UrValue.Number(other, line, Argument(function, parameter)),
    };

    private static int Int(object[] a, int i, int line, string function, string parameter) => a[i] switch
    {
        int n => n,
        double d when d != Math.Floor(d) =>
            throw new UrRuntimeException(line, $"{function}: argument '{parameter}' must be an integer, not {UrValue.FormatNumber(d)}"),
        var other => UrValue.Int(other, line, Argument(function, parameter)),
    };

    private static bool Bool(object[] a, int i, int line, string function, string parameter) => a[i] switch
    {
        bool b => b,
        var other => UrValue.Bool(other, line, Argument(function, parameter)),
    };

    private static string Str(object[] a, int i, int line, string function, string parameter) =>
        a[i] as string ?? UrValue.Text(a[i], line, Argument(function, parameter));

    private static double[] Six(object[] a, int i, int line, string function, string parameter) =>
        a[i] is UrPose pose ? pose.Values : UrValue.Six(a[i], line, Argument(function, parameter));

    /// <summary>How a runtime error names an argument: "movel: argument 'a'".</summary>
    private static string Argument(string function, string parameter) => $"{function}: argument '{parameter}'";

    private static bool Given(object value) => !ReferenceEquals(value, NotGiven);
}

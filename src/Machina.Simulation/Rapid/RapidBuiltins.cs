namespace Machina.Simulation.Rapid;

/// <summary>The instructions and functions of the twin, by name (RAPID is not case sensitive).</summary>
internal static partial class RapidBuiltins
{
    /// <summary>Every built-in.</summary>
    public static IReadOnlyDictionary<string, RapidBuiltin> All { get; } =
        new[] { Motion(), Path(), Settings(), Strings(), MathFunctions(), Io(), Misc(), Sockets(), Interrupts(), Events(), SysInfo(), RawBytes(), ErrorRecovery(), DataAndWaits(), Kinematics(), Frames(), Pendant(), MultiMove(), Trigg(), TriggChecks(), Files(), WorldZones(), Udp(), SmartGripper(), Torque() }.SelectMany(x => x)
            .ToDictionary(b => b.Name, StringComparer.OrdinalIgnoreCase);

    private static RapidBuiltinParam P(string name, string? type, bool reference = false) => RapidBuiltin.P(name, type, reference);

    private static RapidBuiltinParam Opt(string name, string? type, bool reference = false) => RapidBuiltin.Opt(name, type, reference);

    private static RapidBuiltinParam Sw(string name) => RapidBuiltin.Sw(name);

    private static RapidBuiltin Instruction(string name, RapidBuiltinParam[] parameters, Action<RapidCall> run) =>
        new(name, null, parameters, call =>
        {
            run(call);
            return null;
        });

    private static RapidBuiltin Function(string name, string returns, RapidBuiltinParam[] parameters, Func<RapidCall, object> run) =>
        new(name, returns, parameters, run);

    private static RapidRuntimeException ArgumentError(RapidCall call, string message) => call.Error(RapidErrorNumbers.ArgValErr, message);
}

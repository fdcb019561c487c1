using System.Text;
using Machina.Simulation.Rapid;

namespace Machina.Benchmarks;

/// <summary>
/// Loads a compiled-style RAPID module of <c>size</c> lines (MoveL to literal robtargets, SetDO, WaitTime) into the motion task of
/// the RAPID twin, as a controller loads a module: reading, parsing and binding (every name resolved, every type checked).
/// </summary>
internal sealed class RapidLoadScenario : Scenario
{
    public override string Name => "rapid-twin-load";

    public override string Title => "Load a RAPID module into the RAPID twin (parse and bind)";

    public override string Unit => "line";

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [10_000, 100_000];

    public override Target Target { get; } = Target.Seconds(1, 100_000, "<= 1 s per 10^5 lines");

    public override Func<object?> Prepare(int size)
    {
        string module = Module(size);
        return () =>
        {
            var twin = new RapidTwinController(new RapidTwinOptions { Signals = [("DO_1", "signaldo")] });
            twin.Load(("Big.mod", module));
            return twin;
        };
    }

    /// <summary>A module shaped like the library's compiled RAPID: data, then main with moves, outputs and waits.</summary>
    private static string Module(int lines)
    {
        var text = new StringBuilder(lines * 110);
        text.Append("MODULE Big\n  PERS tooldata t1 := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];\n  PROC main()\n");
        for (int i = 4; i < lines - 1; i++)
        {
            text.Append((i % 10) switch
            {
                0 => $"    SetDO DO_1, {i % 2};\n",
                5 => "    WaitTime 0.001;\n",
                _ => FormattableString.Invariant($"    MoveL [[{300 + i % 100}, -30, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, z5, t1\\WObj:=wobj0;\n"),
            });
        }
        return text.Append("  ENDPROC\nENDMODULE\n").ToString();
    }
}

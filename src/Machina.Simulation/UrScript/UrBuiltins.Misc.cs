using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    private static void AddMisc(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "textmsg", (m, line, a) =>
        {
            string text = UrValue.ToText(a[0]) + UrValue.ToText(a[1]);
            m.Controller.Pendant.Log(text);
            m.Controller.Arm.Record(line, TwinTraceKind.Message, text);
            return UrNone.Value;
        }, R("s1"), O("s2", ""));
        Add(t, "popup", (m, line, a) =>
        {
            string title = Str(a, 1, line, "popup", "title");
            bool error = Bool(a, 3, line, "popup", "error"), warning = Bool(a, 2, line, "popup", "warning");
            bool blocking = Bool(a, 4, line, "popup", "blocking");
            string text = $"Popup{(error ? " (error)" : warning ? " (warning)" : "")} {title}: {UrValue.ToText(a[0])}";
            m.Controller.Pendant.Log(text);
            m.Controller.Arm.Record(line, TwinTraceKind.Message, text);
            if (blocking)
            {
                FinishBlend(m, line, anyThread: false); // the arm stops at its waypoint while the program waits
            }
            CancellationToken token = m.Cancellation;
            m.Unlocked(() =>
            {
                m.Controller.ShowPopup(UrValue.ToText(a[0]), blocking, token);
                return 0;
            });
            return UrNone.Value;
        }, R("s"), O("title", "Popup"), O("warning", false), O("error", false), O("blocking", false));
        Add(t, "sleep", (m, line, a) =>
        {
            double seconds = Num(a, 0, line, "sleep", "t");
            if (!(seconds >= 0) || !double.IsFinite(seconds))
            {
                throw new UrRuntimeException(line, "sleep: the time 't' must be zero or positive");
            }
            FinishBlend(m, line, anyThread: false);
            CancellationToken token = m.Cancellation;
            m.Unlocked(() =>
            {
                m.Controller.Clock.Wait(seconds, token);
                return 0;
            });
            m.Controller.Arm.Record(line, TwinTraceKind.Wait, $"sleep {UrValue.FormatNumber(seconds)} s");
            return UrNone.Value;
        }, R("t"));
        Add(t, "sync", (m, line, a) =>
        {
            FinishBlend(m, line, anyThread: false);
            CancellationToken token = m.Cancellation;
            m.Unlocked(() =>
            {
                m.Controller.Clock.Wait(StepSeconds, token);
                return 0;
            });
            return UrNone.Value;
        });
        Add(t, "get_steptime", (m, line, a) => StepSeconds);
        Add(t, "set_tool_voltage", (m, line, a) => Int(a, 0, line, "set_tool_voltage", "voltage") is 0 or 12 or 24
            ? UrNone.Value
            : throw new UrRuntimeException(line, "set_tool_voltage: the voltage must be 0, 12 or 24"), R("voltage"));
    }

    /// <summary>The controller's control period: 2 ms (500 Hz), as the Script Manual says.</summary>
    private const double StepSeconds = 0.002;
}

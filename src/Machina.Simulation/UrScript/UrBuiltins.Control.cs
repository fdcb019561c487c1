namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// The control functions of UR's clients (UR client library's <c>external_control.urscript</c>, ur_rtde's control script)
    /// that need a force or a person's hand to act: the twin has neither, so each is checked as the Script Manual describes
    /// its arguments, switched on or off in <see cref="UrTwinController.Modes"/>, and the arm does what it would with nothing
    /// touching it (approximated, docs/simulation.md): in force mode and in freedrive it stands (no force acts on it), tool
    /// contact never happens, the force/torque sensor reads zero.
    /// </summary>
    private static void AddControl(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "force_mode", ForceMode, R("task_frame"), R("selection_vector"), R("wrench"), R("type"), R("limits"));
        Add(t, "end_force_mode", (m, line, a) =>
        {
            m.Controller.Modes.ForceMode = false;
            return UrNone.Value;
        });
        Add(t, "force_mode_set_damping", (m, line, a) => Within(Num(a, 0, line, "force_mode_set_damping", "damping"), 0, 1, line, "force_mode_set_damping", "damping"), R("damping"));
        Add(t, "force_mode_set_gain_scaling", (m, line, a) => Within(Num(a, 0, line, "force_mode_set_gain_scaling", "scaling"), 0, 2, line, "force_mode_set_gain_scaling", "scaling"), R("scaling"));
        Add(t, "freedrive_mode", (m, line, a) =>
        {
            Six(a, 0, line, "freedrive_mode", "freeAxes");
            Six(a, 1, line, "freedrive_mode", "feature");
            FinishBlend(m, line);
            m.Controller.Modes.Freedrive = true;
            return UrNone.Value;
        }, O("freeAxes", new UrList([1, 1, 1, 1, 1, 1])), O("feature", new UrPose(new double[6])));
        Add(t, "end_freedrive_mode", (m, line, a) =>
        {
            m.Controller.Modes.Freedrive = false;
            return UrNone.Value;
        });
        Add(t, "tool_contact", (m, line, a) =>
        {
            Six(a, 0, line, "tool_contact", "direction");
            return 0; // no contact: nothing touches the twin's tool
        }, R("direction"));
        Add(t, "set_gravity", (m, line, a) =>
        {
            m.Controller.Modes.Gravity = Three(a, 0, line, "set_gravity", "d");
            return UrNone.Value;
        }, R("d"));
        Add(t, "set_target_payload", (m, line, a) =>
        {
            Three(a, 1, line, "set_target_payload", "cog");
            Six(a, 2, line, "set_target_payload", "inertia");
            double seconds = Num(a, 3, line, "set_target_payload", "transition_time");
            if (!(seconds >= 0) || !double.IsFinite(seconds))
            {
                throw new UrRuntimeException(line, "set_target_payload: argument 'transition_time' must be zero or positive");
            }
            return SetPayload(m, line, [a[0], a[1]]);
        }, R("m"), R("cog"), O("inertia", new UrList([0.0, 0.0, 0.0, 0.0, 0.0, 0.0])), O("transition_time", 0.0));
        Add(t, "zero_ftsensor", (m, line, a) => UrNone.Value);
        AddSensorInput(t, "ft_rtde_input_enable");
        Add(t, "set_tool_communication", (m, line, a) => UrNone.Value,
            R("enabled"), R("baud_rate"), R("parity"), R("stop_bits"), R("rx_idle_chars"), R("tx_idle_chars"));
        Add(t, "get_joint_positions", (m, line, a) => UrGeometry.FromJoints(m.Controller.Arm.Joints));
        Add(t, "get_actual_joint_positions_history", (m, line, a) =>
        {
            int steps = Int(a, 0, line, "get_actual_joint_positions_history", "steps");
            return steps >= 0
                ? UrGeometry.FromJoints(m.Controller.Arm.Joints) // the twin keeps no history per control step: where the arm is
                : throw new UrRuntimeException(line, "get_actual_joint_positions_history: argument 'steps' must be zero or positive");
        }, O("steps", 0));
        Add(t, "get_list_length", (m, line, a) => a[0] is UrList list
            ? list.Items.Length
            : throw new UrRuntimeException(line, $"get_list_length: argument 'v' must be an array, not {UrValue.TypeName(a[0])}"), R("v"));
        Add(t, "rtde_set_watchdog", (m, line, a) =>
        {
            string variable = Str(a, 0, line, "rtde_set_watchdog", "variable_name");
            double frequency = Num(a, 1, line, "rtde_set_watchdog", "min_frequency");
            string asked = Str(a, 2, line, "rtde_set_watchdog", "action");
            string action = asked.ToLowerInvariant(); // in any case: UR's own RTDE example program asks for "PAUSE"
            if (!(frequency >= 0) || !double.IsFinite(frequency))
            {
                throw new UrRuntimeException(line, "rtde_set_watchdog: argument 'min_frequency' must be zero or positive");
            }
            if (action is not ("ignore" or "pause" or "stop"))
            {
                throw new UrRuntimeException(line, $"rtde_set_watchdog: argument 'action' must be \"ignore\", \"pause\" or \"stop\", not \"{asked}\"");
            }
            m.Controller.Watchdog.Set(variable, frequency, action);
            return UrNone.Value;
        }, R("variable_name"), R("min_frequency"), O("action", "pause"));
    }

    /// <summary>
    /// A function that takes an external force/torque sensor's readings from RTDE (<c>ft_rtde_input_enable</c>, and its older name
    /// <c>enable_external_ft_sensor</c>): its arguments are checked; the twin has no force sensing.
    /// </summary>
    private static void AddSensorInput(Dictionary<string, UrBuiltin> t, string name) => Add(t, name, (m, line, a) =>
    {
        Bool(a, 0, line, name, "enable");
        Num(a, 1, line, name, "sensor_mass");
        Three(a, 2, line, name, "sensor_measuring_offset");
        Three(a, 3, line, name, "sensor_cog");
        return UrNone.Value;
    }, R("enable"), O("sensor_mass", 0.0), O("sensor_measuring_offset", new UrList([0.0, 0.0, 0.0])), O("sensor_cog", new UrList([0.0, 0.0, 0.0])));

    /// <summary>force_mode: its arguments checked as the Script Manual gives them; the mode switched on (the arm stands: no force acts on it).</summary>
    private static object ForceMode(UrMachine m, int line, object[] a)
    {
        Six(a, 0, line, "force_mode", "task_frame");
        foreach (double s in Six(a, 1, line, "force_mode", "selection_vector"))
        {
            if (s is not (0 or 1))
            {
                throw new UrRuntimeException(line, "force_mode: the selection vector's elements must be 0 or 1");
            }
        }
        Six(a, 2, line, "force_mode", "wrench");
        int type = Int(a, 3, line, "force_mode", "type");
        if (type is < 1 or > 3)
        {
            throw new UrRuntimeException(line, $"force_mode: argument 'type' must be 1, 2 or 3, not {type}");
        }
        Six(a, 4, line, "force_mode", "limits");
        FinishBlend(m, line);
        m.Controller.Modes.ForceMode = true;
        return UrNone.Value;
    }

    private static object Within(double value, double low, double high, int line, string function, string parameter) =>
        value >= low && value <= high
            ? UrNone.Value
            : throw new UrRuntimeException(line, FormattableString.Invariant($"{function}: argument '{parameter}' must be between {low} and {high}, not {UrValue.FormatNumber(value)}"));

    /// <summary>A vector of three numbers (a direction, a centre of gravity).</summary>
    private static double[] Three(object[] a, int i, int line, string function, string parameter) =>
        a[i] is UrList { Items.Length: 3 } list
            ? [.. list.Items.Select(v => UrValue.Number(v, line, $"{function}: argument '{parameter}'"))]
            : throw new UrRuntimeException(line, $"{function}: argument '{parameter}' must be an array of 3 numbers, not {UrValue.Describe(a[i])}");
}

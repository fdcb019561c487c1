namespace Machina.Simulation.Krl;

/// <summary>
/// The basic package as the program templates and inline forms use it: BAS and its commands, the global data of $CONFIG.DAT
/// they read (PDAT_ACT, LDAT_ACT, FDAT_ACT, PDEFAULT, LDEFAULT, TOOL_DATA, BASE_DATA, HOME, XHOME), $BWDSTART and $H_POS, and
/// SET_CD_PARAMS. BAS writes the system variables as the KUKA system software's BAS.SRC does, in the twin's units: the axes'
/// speed and acceleration in % ($VEL_AXIS, $ACC_AXIS), the path's in m/s and m/s² ($VEL.CP, $ACC.CP), the approximation
/// distances ($APO), and the tool and base from TOOL_DATA and BASE_DATA.
/// </summary>
internal static class KrlBasicPackage
{
    /// <summary>Number of tools (TOOL_DATA[1..16]) and bases (BASE_DATA[1..32]) as a KR C4 has them.</summary>
    public const int Tools = 16, Bases = 32;

    /// <summary>Adds BAS, SET_CD_PARAMS and the global template data to <paramref name="environment"/>.</summary>
    public static void AddTo(KrlEnvironment environment)
    {
        void Add(string name, KrlType type, object value) => environment.System[name] = new KrlCell(name, type, value);
        KrlType tools = KrlType.Array(KrlTypes.Frame, Tools), bases = KrlType.Array(KrlTypes.Frame, Bases);
        Add("TOOL_DATA", tools, KrlValues.Default(tools));
        Add("BASE_DATA", bases, KrlValues.Default(bases));
        Add("PDEFAULT", KrlTemplateTypes.Pdat, KrlTemplateTypes.Motion(KrlTemplateTypes.Pdat, 100, 100, 100));
        Add("LDEFAULT", KrlTemplateTypes.Ldat, KrlTemplateTypes.Motion(KrlTemplateTypes.Ldat, 2, 100, 100));
        Add("PDAT_ACT", KrlTemplateTypes.Pdat, KrlTemplateTypes.Motion(KrlTemplateTypes.Pdat, 100, 100, 100));
        Add("LDAT_ACT", KrlTemplateTypes.Ldat, KrlTemplateTypes.Motion(KrlTemplateTypes.Ldat, 2, 100, 100));
        var frames = (KrlStructValue)KrlValues.Default(KrlTemplateTypes.Fdat);
        frames.Values[2] = new KrlEnumValue("BASE");
        Add("FDAT_ACT", KrlTemplateTypes.Fdat, frames);
        Add("HOME", KrlTypes.Axis, Home(KrlTypes.Axis));
        Add("XHOME", KrlTypes.E6Axis, Home(KrlTypes.E6Axis));
        Add("$H_POS", KrlTypes.E6Axis, Home(KrlTypes.E6Axis));
        Add("$BWDSTART", KrlType.Bool, false);
        environment.Builtins["BAS"] = new KrlBuiltin("BAS", null, [new(KrlType.Enum), new(KrlType.Real, Optional: true)], Bas);
        environment.Builtins["SET_CD_PARAMS"] = new KrlBuiltin("SET_CD_PARAMS", null, [KrlBuiltinParameter.Int], (_, _) => null);
    }

    /// <summary>The home position of the templates' $CONFIG.DAT: A2 -90°, A3 +90°, the other axes at 0.</summary>
    private static KrlStructValue Home(KrlType type)
    {
        var home = (KrlStructValue)KrlValues.Default(type);
        home.Values[1] = -90.0;
        home.Values[2] = 90.0;
        return home;
    }

    /// <summary>BAS(#command[, value]): the basic package's motion settings (see the class).</summary>
    private static object? Bas(KrlMachine machine, object[] a)
    {
        KrlTwinController controller = machine.Controller;
        KrlEnvironment environment = controller.Environment;
        string command = ((KrlEnumValue)a[0]).Name.ToUpperInvariant();
        double value = a.Length > 1 ? KrlValues.ToReal(a[1]) : 0;
        KrlStructValue Struct(string name) => (KrlStructValue)environment.System[name].Value;
        switch (command)
        {
            case "INITMOV":
                controller.InitialiseMotion();
                Write(environment, "$BWDSTART", false);
                break;
            case "VEL_PTP":
                FillAxes(environment, "$VEL_AXIS", value);
                break;
            case "ACC_PTP":
                FillAxes(environment, "$ACC_AXIS", value);
                break;
            case "VEL_CP":
                Struct("$VEL").Values[0] = value;
                break;
            case "ACC_CP":
                Struct("$ACC").Values[0] = controller.Options.DefaultCpAcceleration * value / 100;
                break;
            case "TOOL":
                Write(environment, "$TOOL", FrameData(environment, "TOOL_DATA", (int)value, Tools));
                break;
            case "BASE":
                Write(environment, "$BASE", FrameData(environment, "BASE_DATA", (int)value, Bases));
                break;
            case "FRAMES":
                Frames(environment);
                break;
            case "PTP_DAT":
                PtpData(environment, Struct("PDAT_ACT").Number("VEL"));
                break;
            case "PTP_PARAMS":
                Frames(environment);
                PtpData(environment, value * Struct("PDAT_ACT").Number("VEL") / 100);
                break;
            case "CP_DAT":
                CpData(controller, Struct("LDAT_ACT").Number("VEL"));
                break;
            case "CP_PARAMS":
                Frames(environment);
                CpData(controller, value);
                break;
            default:
                throw new KrlRuntimeException($"BAS(#{command}) is not supported by the twin (it runs #INITMOV, #VEL_PTP, #ACC_PTP, #VEL_CP, #ACC_CP, #TOOL, #BASE, #FRAMES, #PTP_DAT, #PTP_PARAMS, #CP_DAT, #CP_PARAMS)");
        }
        return null;
    }

    /// <summary>$TOOL and $BASE from FDAT_ACT's TOOL_NO and BASE_NO.</summary>
    private static void Frames(KrlEnvironment environment)
    {
        var frames = (KrlStructValue)environment.System["FDAT_ACT"].Value;
        Write(environment, "$TOOL", FrameData(environment, "TOOL_DATA", (int)frames.Real(0), Tools));
        Write(environment, "$BASE", FrameData(environment, "BASE_DATA", (int)frames.Real(1), Bases));
    }

    /// <summary>A PTP's settings from PDAT_ACT: axis speed <paramref name="velocity"/> %, its acceleration, its approximation distance.</summary>
    private static void PtpData(KrlEnvironment environment, double velocity)
    {
        var data = (KrlStructValue)environment.System["PDAT_ACT"].Value;
        FillAxes(environment, "$VEL_AXIS", velocity);
        FillAxes(environment, "$ACC_AXIS", data.Number("ACC"));
        ((KrlStructValue)environment.System["$APO"].Value).Values[1] = KrlValues.Box((int)Math.Clamp(Math.Round(data.Number("APO_DIST")), 0, 100));
    }

    /// <summary>A CP motion's settings from LDAT_ACT: path speed <paramref name="velocity"/> m/s, its acceleration (%), its approximation distance.</summary>
    private static void CpData(KrlTwinController controller, double velocity)
    {
        KrlEnvironment environment = controller.Environment;
        var data = (KrlStructValue)environment.System["LDAT_ACT"].Value;
        ((KrlStructValue)environment.System["$VEL"].Value).Values[0] = velocity;
        ((KrlStructValue)environment.System["$ACC"].Value).Values[0] = controller.Options.DefaultCpAcceleration * data.Number("ACC") / 100;
        ((KrlStructValue)environment.System["$APO"].Value).Values[2] = data.Number("APO_DIST");
    }

    private static void FillAxes(KrlEnvironment environment, string name, double percent)
    {
        if (percent is < 0 or > 100)
        {
            throw new KrlRuntimeException($"Value assignment inadmissible: {name} takes 0 to 100 %, not {percent}");
        }
        Array.Fill(((KrlArrayValue)environment.System[name].Value).Objects, KrlValues.Box((int)Math.Max(1, Math.Round(percent))));
    }

    /// <summary>TOOL_DATA[n] or BASE_DATA[n]; 0 is $NULLFRAME.</summary>
    private static object FrameData(KrlEnvironment environment, string array, int number, int count)
    {
        if (number == 0)
        {
            return KrlValues.Default(KrlTypes.Frame);
        }
        if (number < 0 || number > count)
        {
            throw new KrlRuntimeException($"{array}[{number}] does not exist (1 to {count})");
        }
        return KrlValues.Copy(((KrlArrayValue)environment.System[array].Value)[number - 1]);
    }

    /// <summary>Writes system variable <paramref name="name"/> as an assignment does (its controller hook runs).</summary>
    private static void Write(KrlEnvironment environment, string name, object value)
    {
        KrlCell cell = environment.System[name];
        cell.Value = value;
        cell.Written?.Invoke(-1);
    }
}

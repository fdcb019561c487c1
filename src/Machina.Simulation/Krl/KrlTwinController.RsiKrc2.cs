namespace Machina.Simulation.Krl;

/// <summary>
/// RSI 2 of the KR C2 (KUKA.Ethernet RSI XML), whose programs build the signal flow object by object: ST_ETHERNET and
/// ST_AXISCORR create objects in a container (their handles OUT), ST_NEWLINK links an output to an input (indices from 1),
/// ST_SETPARAM sets a parameter by number (AXISCORR: 1 the mode, 0 absolute and 1 relative; 2 to 7 the lower limits of A1 to
/// A6, 14 to 19 the upper), ST_ON starts it in the 12 ms cycle, ST_SKIPSENS is the sensor-guided motion RSI_MOVECORR is, ST_OFF
/// ends it. They return RSIERR (#RSIOK).
/// </summary>
internal sealed partial class KrlTwinController
{
    private readonly Dictionary<int, (int Container, RsiObject Object)> _rsiHandles = [];
    private int _rsiLastContainer = -1;

    private void AddRsiKrc2()
    {
        KrlType error = KrlTypes.RsiError;
        KrlBuiltinParameter handle = new(KrlType.Int, IsOut: true), number = KrlBuiltinParameter.Int;
        void Add(string name, KrlType? returns, KrlBuiltinParameter[] parameters, Func<KrlMachine, object[], object?> run) =>
            Environment.Builtins[name] = new KrlBuiltin(name, returns, parameters, run);
        Add("ST_ETHERNET", error, [handle, number, KrlBuiltinParameter.Text], (_, a) =>
        {
            string configuration = Str(a[2]);
            try
            {
                RsiEthernetConfiguration.Parse(configuration, RsiFile(configuration, "Ethernet configuration"));
            }
            catch (FormatException ex)
            {
                throw new KrlRuntimeException(ex.Message);
            }
            RsiObject ethernet = RsiNewObject("ETHERNET", KrlValues.ToInt(a[1]), (KrlPlace)a[0]);
            ethernet.Parameters["ConfigFile"] = configuration;
            ethernet.Parameters["Timeout"] = "100";
            return RsiErrorOk;
        });
        Add("ST_AXISCORR", error, [handle, number], (_, a) =>
        {
            RsiNewObject("AXISCORR", KrlValues.ToInt(a[1]), (KrlPlace)a[0]).Parameters["Mode"] = "0";
            return RsiErrorOk;
        });
        Add("ST_NEWLINK", error, [number, number, number, number], (_, a) =>
        {
            RsiObject source = RsiHandle(KrlValues.ToInt(a[0])).Object;
            RsiHandle(KrlValues.ToInt(a[2])).Object.Inputs[KrlValues.ToInt(a[3])] = new RsiLink(source.Id, KrlValues.ToInt(a[1]));
            return RsiErrorOk;
        });
        Add("ST_SETPARAM", error, [number, number, KrlBuiltinParameter.Real], (_, a) =>
        {
            RsiObject target = RsiHandle(KrlValues.ToInt(a[0])).Object;
            int index = KrlValues.ToInt(a[1]);
            string name = target.Type == "AXISCORR" ? index switch
            {
                1 => "Mode",
                >= 2 and <= 7 => $"LowerLimA{index - 1}",
                >= 14 and <= 19 => $"UpperLimA{index - 13}",
                _ => $"#{index}",
            } : $"#{index}";
            target.Parameters[name] = KrlValues.ToReal(a[2]).ToString("R", System.Globalization.CultureInfo.InvariantCulture);
            return RsiErrorOk;
        });
        Add("ST_ON", error, [], (_, _) =>
        {
            RsiContext context = RsiContextOf(_rsiLastContainer);
            RsiStart(context, context.Objects.Find(o => o.Type == "AXISCORR") is { } axes && axes.Number("Mode", 0) == 1, 0.012);
            return RsiErrorOk;
        });
        Add("ST_SKIPSENS", null, [], (m, _) => RsiMoveCorr(m));
        Add("ST_OFF", error, [], (_, _) =>
        {
            RsiOff();
            return RsiErrorOk;
        });
    }

    private static KrlEnumValue RsiErrorOk => new("RSIOK");

    private RsiObject RsiNewObject(string type, int container, KrlPlace handle)
    {
        lock (_gate)
        {
            if (!_rsiContexts.TryGetValue(container, out RsiContext? context))
            {
                context = RsiContext.Empty($"container {container}");
                _rsiContexts[container] = context;
            }
            int id = _rsiHandles.Count + 1;
            var created = new RsiObject(type, $"{type}{id}");
            context.Objects.Add(created);
            _rsiHandles[id] = (container, created);
            _rsiLastContainer = container;
            handle.Set(id);
            return created;
        }
    }

    private (int Container, RsiObject Object) RsiHandle(int handle)
    {
        lock (_gate)
        {
            return _rsiHandles.TryGetValue(handle, out var found) ? found : throw new KrlRuntimeException($"RSI: no object has the handle {handle}");
        }
    }
}

using System.Globalization;
using System.Xml.Linq;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// The RobotSensorInterface (RSI 3 and 4 of the KUKA System Software) as the published RSI clients use it: RSI_CREATE loads a
/// context (.rsix, or .rsi.xml for "name.rsi"), RSI_ON starts it (#ABSOLUTE or #RELATIVE corrections, #IPO 12 ms or #IPO_FAST
/// 4 ms cycles), RSI_MOVECORR exchanges a datagram with the sensor every cycle and moves the axes by its AXISCORR corrections
/// until a STOP object fires, RSI_OFF and RSI_DELETE end it; RSI_SETPUBLICPAR/RSI_GETPUBLICPAR set and read parameters.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>The value RSI routines return when they succeeded (RSIOK).</summary>
    public const int RsiOk = 0;

    private readonly Dictionary<string, string> _rsiFiles = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<int, RsiContext> _rsiContexts = [];
    private RsiSession? _rsiOn;
    private (int Cycles, int Late) _rsiLastCycles;

    /// <summary>
    /// How many RSI cycles ran from the last RSI_ON (to RSI_OFF, or until now) and how many of them had no answer in time: the
    /// datagrams flow from RSI_ON on, during RSI_MOVECORR and between motions.
    /// </summary>
    public (int Cycles, int Late) RsiCycles => _rsiOn is { } on ? (on.Cycles, on.Delay) : _rsiLastCycles;

    /// <summary>
    /// Adds a file of the controller's SensorInterface folder (an RSI context <c>.rsix</c> or <c>.rsi.xml</c>, or an ETHERNET
    /// object's configuration <c>.xml</c>), read when a program creates its context.
    /// </summary>
    public void AddRsiFile(string name, string text)
    {
        lock (_gate)
        {
            _rsiFiles[name] = text;
        }
    }

    private void AddRsi()
    {
        KrlBuiltinParameter text = KrlBuiltinParameter.Text;
        void Add(string name, KrlType? returns, KrlBuiltinParameter[] parameters, Func<KrlMachine, object[], object?> run) =>
            Environment.Builtins[name] = new KrlBuiltin(name, returns, parameters, run);
        Environment.System["RSIOK"] = new KrlCell("RSIOK", KrlType.Int, RsiOk) { ReadOnly = true };
        Add("RSI_CREATE", KrlType.Int, [text, new(KrlType.Int, IsOut: true), new(KrlType.Bool, Optional: true)], (_, a) => RsiCreate(Str(a[0]), (KrlPlace)a[1]));
        Add("RSI_DELETE", KrlType.Int, [KrlBuiltinParameter.Int], (_, a) => RsiDelete(KrlValues.ToInt(a[0])));
        Add("RSI_ON", KrlType.Int, [new(KrlType.Enum, Optional: true), new(KrlType.Enum, Optional: true)], (_, a) => RsiOn(a));
        Add("RSI_OFF", KrlType.Int, [], (_, _) => RsiOff());
        Add("RSI_MOVECORR", null, [new(KrlType.Real, Optional: true), new(KrlType.Real, Optional: true)], (m, _) => RsiMoveCorr(m));
        Add("RSI_SETPUBLICPAR", KrlType.Int, [KrlBuiltinParameter.Int, text, text, KrlBuiltinParameter.Real], (_, a) =>
        {
            RsiParameterOwner(a)[Str(a[2])] = KrlValues.ToReal(a[3]).ToString("R", CultureInfo.InvariantCulture);
            return RsiOk;
        });
        Add("RSI_GETPUBLICPAR", KrlType.Int, [KrlBuiltinParameter.Int, text, text, new(KrlType.Real, IsOut: true)], (_, a) =>
        {
            ((KrlPlace)a[3]).Set(double.Parse(RsiParameterOwner(a).GetValueOrDefault(Str(a[2]), "0"), CultureInfo.InvariantCulture));
            return RsiOk;
        });
    }

    private Dictionary<string, string> RsiParameterOwner(object[] a)
    {
        RsiContext context = RsiContextOf(KrlValues.ToInt(a[0]));
        string id = Str(a[1]);
        return (context.Find(id) ?? throw new KrlRuntimeException($"RSI: the context {context.Name} has no object {id}")).Parameters;
    }

    private RsiContext RsiContextOf(int container)
    {
        lock (_gate)
        {
            return _rsiContexts.GetValueOrDefault(container) ?? throw new KrlRuntimeException($"RSI: no context was created with the container ID {container} (RSI_CREATE)");
        }
    }

    private string RsiFile(string name, string what)
    {
        lock (_gate)
        {
            return _rsiFiles.GetValueOrDefault(name) ?? throw new KrlRuntimeException($"RSI: the {what} {name} is not in the controller's SensorInterface folder");
        }
    }

    /// <summary>RSI_CREATE(name, container ID): "name" is name.rsix (RSI 4); "name.rsi" is name.rsi.xml (RSI 3).</summary>
    private int RsiCreate(string name, KrlPlace container)
    {
        string file = name.EndsWith(".rsi", StringComparison.OrdinalIgnoreCase) ? name + ".xml" : name + ".rsix";
        RsiContext context;
        try
        {
            context = RsiContext.Parse(file, RsiFile(file, "context"));
            foreach (RsiObject ethernet in context.Objects.Where(o => o.Type == "ETHERNET"))
            {
                string configuration = ethernet.Parameters.GetValueOrDefault("ConfigFile", "");
                RsiEthernetConfiguration.Parse(configuration, RsiFile(configuration, "Ethernet configuration"));
            }
        }
        catch (FormatException ex)
        {
            throw new KrlRuntimeException(ex.Message);
        }
        int id;
        lock (_gate)
        {
            id = _rsiContexts.Count == 0 ? 1 : _rsiContexts.Keys.Max() + 1;
            _rsiContexts[id] = context;
        }
        container.Set(id);
        return RsiOk;
    }

    private int RsiDelete(int container)
    {
        RsiContext context = RsiContextOf(container);
        if (ReferenceEquals(context, _rsiOn?.Context))
        {
            throw new KrlRuntimeException("RSI: RSI_DELETE of the context that is on (RSI_OFF first)");
        }
        lock (_gate)
        {
            _rsiContexts.Remove(container);
        }
        return RsiOk;
    }

    /// <summary>RSI_ON([#ABSOLUTE | #RELATIVE], [#IPO | #IPO_FAST]): the last context created runs; the defaults are #RELATIVE and #IPO.</summary>
    private int RsiOn(object[] a)
    {
        string mode = a.Length > 0 && a[0] is KrlEnumValue m ? m.Name.ToUpperInvariant() : "RELATIVE";
        string sensor = a.Length > 1 && a[1] is KrlEnumValue s ? s.Name.ToUpperInvariant() : "IPO";
        if (mode is not ("ABSOLUTE" or "RELATIVE") || sensor is not ("IPO" or "IPO_FAST"))
        {
            throw new KrlRuntimeException($"RSI_ON(#{mode}, #{sensor}): the correction mode is #ABSOLUTE or #RELATIVE, the sensor mode #IPO or #IPO_FAST");
        }
        RsiContext context;
        lock (_gate)
        {
            context = _rsiContexts.Count > 0 ? _rsiContexts[_rsiContexts.Keys.Max()] : throw new KrlRuntimeException("RSI_ON: no context was created (RSI_CREATE)");
        }
        RsiStart(context, mode == "RELATIVE", sensor == "IPO_FAST" ? 0.004 : 0.012);
        return RsiOk;
    }

    /// <summary>
    /// Switches <paramref name="context"/> on: its ETHERNET object starts exchanging a datagram with the sensor every cycle, as the
    /// controller does from RSI_ON on; between motions the twin sends the robot's values and reads the sensor's (kept for the next
    /// RSI_MOVECORR's HOLDON values and late count) without moving the arm.
    /// </summary>
    private void RsiStart(RsiContext context, bool relative, double cycle)
    {
        if (_rsiOn is not null)
        {
            throw new KrlRuntimeException("RSI_ON: RSI is on already (RSI_OFF first)");
        }
        RsiObject ethernet = context.Objects.Find(o => o.Type == "ETHERNET") ?? throw new KrlRuntimeException($"RSI: the context {context.Name} has no ETHERNET object");
        string file = ethernet.Parameters.GetValueOrDefault("ConfigFile", "");
        RsiEthernetConfiguration configuration;
        try
        {
            configuration = RsiEthernetConfiguration.Parse(file, RsiFile(file, "Ethernet configuration"));
        }
        catch (FormatException ex)
        {
            throw new KrlRuntimeException(ex.Message);
        }
        TimeProvider time = Options.Time;
        var session = new RsiSession(context, ethernet, configuration, relative, cycle)
        {
            Ipoc = (long)(Clock.Seconds * 1000),
            Commanded = (Arm.Joints, Arm.Tcp),
            Deadline = time.GetTimestamp() + CycleTicks(cycle, time),
        };
        _rsiOn = session;
        bool first = true;
        var sleep = new TwinSleep(); // the thread's own: the clock's sleeper belongs to the interpreter's thread
        session.Start(stop =>
        {
            // The first cycle is RSI_MOVECORR's when it follows RSI_ON; then each cycle starts where the one before ended.
            double rest = first ? cycle : time.GetElapsedTime(time.GetTimestamp(), session.Deadline - CycleTicks(cycle, time)).TotalSeconds;
            first = false;
            if (rest > 0)
            {
                sleep.Wait(time, TimeSpan.FromSeconds(rest), stop);
            }
        }, stop =>
        {
            if (time.GetTimestamp() >= session.Deadline - CycleTicks(cycle, time))
            {
                RsiCycle(session, session.Commanded.Axes, session.Commanded.Tcp, stop);
            }
        });
    }

    private static long CycleTicks(double cycle, TimeProvider time) => (long)(cycle * time.TimestampFrequency);

    private int RsiOff()
    {
        RsiSession? session = _rsiOn;
        if (session is null)
        {
            return RsiOk;
        }
        _rsiOn = null;
        session.Dispose();
        _rsiLastCycles = (session.Cycles, session.Delay);
        return session.Fault is { } fault ? throw new KrlRuntimeException(fault) : RsiOk;
    }

    /// <summary>RSI ends with the program: the exchange stops (the program's end, an error, a reset).</summary>
    private void EndRsi()
    {
        if (_rsiOn is { } session)
        {
            _rsiOn = null;
            session.Dispose();
            _rsiLastCycles = (session.Cycles, session.Delay);
        }
    }

    /// <summary>
    /// One RSI cycle's exchange: the ETHERNET object sends the robot's values (<paramref name="commanded"/> and
    /// <paramref name="commandedTcp"/> the program's command) and waits, until the cycle ends, for the answer with the same IPOC, whose
    /// values go into the session's outputs. More late answers in a row than the ETHERNET object's Timeout stop the program
    /// ("RSITimeout"). Returns whether the answer came in time.
    /// </summary>
    private bool RsiCycle(RsiSession session, Joints commanded, Pose commandedTcp, CancellationToken cancellation)
    {
        TimeProvider time = Options.Time;
        long cycle = CycleTicks(session.Cycle, time), now = time.GetTimestamp();
        if (session.Deadline < now)
        {
            session.Deadline = now + cycle; // behind (a loaded machine): this cycle starts now
        }
        session.Cycles++;
        session.Ipoc += (long)Math.Round(session.Cycle * 1000);
        RsiInputs(session.Context, session.Ethernet, session.Inputs, session.Outputs);
        var robot = new RsiRobotValues(CartesianValues(Arm.Tcp), CartesianValues(commandedTcp), Arm.Joints.ToArray(), commanded.ToArray());
        RsiExchange exchange = session.Exchange;
        exchange.Send(exchange.Document(robot, session.Inputs, session.Delay, session.Ipoc));
        bool onlySend = exchange.Configuration.OnlySend;
        XElement? answer = onlySend ? null : exchange.Answer(session.Ipoc, time, session.Deadline, cancellation);
        session.Deadline += cycle;
        if (answer is null && !onlySend)
        {
            session.Delay++;
            int timeout = Math.Max((int)session.Ethernet.Number("Timeout", 10), 1);
            if (++session.LateInRow >= timeout)
            {
                throw new KrlRuntimeException($"Signal flow (running): Object {session.Ethernet.Id} returns error RSITimeout: {session.LateInRow} answers in a row missed their {session.Cycle * 1000:0} ms cycle (Timeout {timeout})");
            }
        }
        else
        {
            session.LateInRow = 0;
        }
        exchange.Read(answer, session.Outputs);
        return answer is not null;
    }

    /// <summary>
    /// RSI_MOVECORR(): the sensor-guided motion. Every cycle the ETHERNET object sends the robot's values and waits, until the cycle
    /// ends, for the answer with the same IPOC; AXISCORR moves the axes by the corrections it feeds (from where the motion started
    /// with #ABSOLUTE, added up with #RELATIVE; within LowerLimAn/UpperLimAn), AXISCORRMON stops the program when one is beyond
    /// MaxAn, and the motion ends when a STOP object's input is not 0. More late answers in a row than the ETHERNET object's
    /// Timeout stop the program ("RSITimeout").
    /// </summary>
    private object? RsiMoveCorr(KrlMachine machine)
    {
        RsiSession session = _rsiOn ?? throw new KrlRuntimeException("RSI_MOVECORR: RSI is not on (RSI_ON)");
        Arm.FinishBlend(machine.Cancellation);
        RsiContext context = session.Context;
        using IDisposable turn = session.Take(machine.Cancellation);
        if (session.Fault is { } fault)
        {
            throw new KrlRuntimeException(fault);
        }
        Joints start = Arm.Joints;
        Pose startTcp = Arm.Tcp;
        session.Commanded = (start, startTcp);
        double[] total = new double[6], outputs = session.Outputs;
        int firstCycle = session.Cycles, firstDelay = session.Delay;
        TimeProvider time = Options.Time;
        bool stop = false;
        try
        {
            while (!stop)
            {
                machine.Cancellation.ThrowIfCancellationRequested();
                RsiCycle(session, start, startTcp, machine.Cancellation);
                double Input(RsiObject o, int index) => o.Inputs.TryGetValue(index, out RsiLink? link) ? RsiOutput(context, link, outputs) : 0;
                foreach (RsiObject o in context.Objects)
                {
                    switch (o.Type)
                    {
                        case "AXISCORR":
                            for (int i = 0; i < 6; i++)
                            {
                                double correction = Input(o, i + 1);
                                double sum = session.Relative ? total[i] + correction : correction;
                                total[i] = Math.Clamp(sum, o.Number($"LowerLimA{i + 1}", -5), o.Number($"UpperLimA{i + 1}", 5));
                            }
                            break;
                        case "AXISCORRMON":
                            for (int i = 0; i < 6; i++)
                            {
                                if (Math.Abs(total[i]) > o.Number($"MaxA{i + 1}", double.MaxValue))
                                {
                                    throw new KrlRuntimeException(FormattableString.Invariant($"RSI: {o.Id}: the correction of A{i + 1} ({total[i]:0.###} deg) is beyond MaxA{i + 1} ({o.Number($"MaxA{i + 1}", 0):0.###} deg)"));
                                }
                            }
                            break;
                        case "STOP":
                            stop |= Input(o, 1) != 0;
                            break;
                        case "MAP2DIGOUT":
                            RsiSetOutput((int)o.Number("Index", 1), Input(o, 1) != 0);
                            break;
                    }
                }
                var target = new Joints(start.J1 + total[0], start.J2 + total[1], start.J3 + total[2], start.J4 + total[3], start.J5 + total[4], start.J6 + total[5]);
                RequireSoftLimits(target);
                Arm.MoveTo(target, 0, machine.Line, "RSI", machine.Cancellation, trace: false);
                if (Clock.RealTime)
                {
                    TimeSpan rest = time.GetElapsedTime(time.GetTimestamp(), session.Deadline - CycleTicks(session.Cycle, time));
                    if (rest > TimeSpan.Zero)
                    {
                        Clock.WaitAside(rest.TotalSeconds, machine.Cancellation);
                    }
                }
                Clock.Add(session.Cycle);
            }
        }
        finally
        {
            Arm.Record(machine.Line, TwinTraceKind.Motion, FormattableString.Invariant($"RSI_MOVECORR ({session.Cycles - firstCycle} cycles of {session.Cycle * 1000:0} ms, {session.Delay - firstDelay} late)"));
        }
        return null;
    }

    /// <summary>The value an object's output gives: the ETHERNET object's received values, DIGIN's $IN and DIGOUT's $OUT (0 or 1).</summary>
    private double RsiOutput(RsiContext context, RsiLink link, double[] received)
    {
        RsiObject source = context.Find(link.Source)!;
        return source.Type switch
        {
            "ETHERNET" => link.Output is >= 1 and <= 64 ? received[link.Output] : 0,
            "DIGIN" => RsiDigital("$IN", (int)source.Number("Index", 1)) ? 1 : 0,
            "DIGOUT" => RsiDigital("$OUT", (int)source.Number("Index", 1)) ? 1 : 0,
            _ => 0,
        };
    }

    private void RsiInputs(RsiContext context, RsiObject ethernet, double[] inputs, double[] received)
    {
        foreach ((int index, RsiLink link) in ethernet.Inputs)
        {
            if (index is >= 1 and <= 64)
            {
                inputs[index] = RsiOutput(context, link, received);
            }
        }
    }

    private bool RsiDigital(string array, int number) =>
        number is >= 1 and <= KrlSystemVariables.DigitalCount && Io.GetBit(array, number - 1);

    private void RsiSetOutput(int number, bool value)
    {
        if (number is < 1 or > KrlSystemVariables.DigitalCount || RsiDigital("$OUT", number) == value)
        {
            return;
        }
        Io.SetBit("$OUT", number - 1, value);
        OutputWritten("$OUT", number - 1);
    }

    private double[] CartesianValues(Pose tcp)
    {
        var position = (KrlStructValue)PositionOf(tcp, Arm.Joints);
        return [.. Enumerable.Range(0, 6).Select(i => (double)position.Values[i])];
    }
}

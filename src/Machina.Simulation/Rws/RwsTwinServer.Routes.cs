using System.Globalization;
using System.Xml.Linq;
using Machina.Simulation.Rapid;
using static Machina.Simulation.Rws.RwsXhtmlWriter;

namespace Machina.Simulation.Rws;

/// <summary>The resources of the twin's Robot Web Services, each acting on the twin (paths and fields: docs/rws.md).</summary>
internal sealed partial class RwsTwinServer
{
    /// <summary>The return code RWS documents for a RAPID data update without mastership.</summary>
    public const long MastershipRequiredCode = -1073414146;

    private readonly List<(int Sequence, int Code, string Title)> _elog = [];
    private string? _master;

    /// <summary>The event log, oldest first: code and title.</summary>
    public IReadOnlyList<(int Code, string Title)> EventLog
    {
        get
        {
            lock (_gate)
            {
                return [.. _elog.Select(e => (e.Code, e.Title))];
            }
        }
    }

    private void Log(int code, string title)
    {
        lock (_gate)
        {
            _elog.Add((_elog.Count + 1, code, title));
        }
    }

    private RwsResponse Handle(RwsRequest request, string session)
    {
        string[] s = request.Path.Trim('/').Split('/');
        string action = request.Query.GetValueOrDefault("action") ?? "";
        bool get = request.Method == "GET";
        try
        {
            return (s, get) switch
            {
                (["rw", "panel", "opmode"], true) => State("panel", Item("pnl-opmode", "opmode", ("opmode", OperationMode))),
                (["rw", "panel", "ctrlstate"], true) => State("panel", Item("pnl-ctrlstate", "ctrlstate", ("ctrlstate", MotorsOn ? "motoron" : "motoroff"))),
                (["rw", "panel", "speedratio"], true) => State("panel", Item("pnl-speedratio", "speedratio", ("speedratio", Text(SpeedRatio)))),
                (["rw", "panel", "speedratio"], false) when action == "setspeedratio" => SetSpeedRatio(request),
                (["rw", "rapid", "execution"], true) => State("rapid", Item("rap-execution", "execution",
                    ("ctrlexecstate", Twin.IsRunning ? "running" : "stopped"), ("cycle", CycleText))),
                (["rw", "rapid", "execution"], false) => Execution(action, request.Form, session),
                (["rw", "rapid", "tasks"], true) => State("rapid", Twin.TaskNames.Select(t => Item("rap-task-li", t,
                    ("name", t), ("excstate", Twin.Task(t).State == RapidProgramState.Running ? "started" : "stopped"),
                    ("tasktype", Twin.Task(t).Type.ToString()), ("motiontask", Twin.Task(t).IsMotionTask ? "TRUE" : "FALSE")))),
                (["rw", "rapid", "tasks", var task], false) when action == "loadmod" => LoadModule(task, request.Form, session),
                (["rw", "rapid", "symbol", "data", "RAPID", var task, var module, var symbol], _) => Symbol(task, module, symbol, get, request.Form, session),
                (["rw", "mastership", ..], false) => Mastership(action, session),
                (["fileservice", ..], _) => FileService(string.Join('/', s[1..]), request, get),
                (["rw", "elog", "0"], true) => EventLogPage(),
                (["rw", "motionsystem", "mechunits", "ROB_1", "jointtarget"], true) => JointTarget(),
                (["rw", "motionsystem", "mechunits", "ROB_1", "robtarget"], true) => RobTarget(),
                (["rw", "iosystem", "signals", ..], _) => Signal(s[^1], get, request.Form),
                (["subscription"], false) => Subscribe(request.Form),
                (["subscription", var id], false) when request.Method == "DELETE" => Unsubscribe(id),
                _ => Error(404, "Not Found", null, $"No resource {request.Method} {request.Path} on the twin's Robot Web Services."),
            };
        }
        catch (Exception ex) when (ex is FormatException or KeyNotFoundException or OverflowException)
        {
            // A field missing or not a number: refused with the reason, the connection kept.
            return Error(400, "Bad Request", null, ex.Message);
        }
    }

    private RwsResponse Mastership(string action, string session)
    {
        lock (_gate)
        {
            if (action == "release")
            {
                if (_master == session)
                {
                    _master = null;
                }
                return RwsResponse.NoContent();
            }
            if (action != "request")
            {
                return Error(400, "Bad Request", null, $"Unknown mastership action \"{action}\".");
            }
            string? other = MastershipHeldBy ?? (_master is not null && _master != session ? "another Robot Web Services client" : null);
            if (other is not null)
            {
                return Error(403, "Forbidden", null, $"Mastership is held by {other}.");
            }
            _master = session;
            return RwsResponse.NoContent();
        }
    }

    private RwsResponse SetSpeedRatio(RwsRequest request)
    {
        if (!OperationMode.Equals("AUTO", StringComparison.OrdinalIgnoreCase))
        {
            return Error(400, "Bad Request", null, $"The speed ratio can be set only in automatic mode; the controller is in {OperationMode}.");
        }
        string text = request.Form.GetValueOrDefault("speed-ratio") ?? throw new FormatException("The form has no speed-ratio field.");
        if (!int.TryParse(text, NumberStyles.Integer, CultureInfo.InvariantCulture, out int ratio) || ratio is < 0 or > 100)
        {
            return Error(400, "Bad Request", null, $"The speed ratio must be a whole number between 0 and 100, not {PrintableText.Of(text)}.");
        }
        SpeedRatio = ratio;
        return RwsResponse.NoContent();
    }

    private RwsResponse EventLogPage()
    {
        lock (_gate)
        {
            // Newest first, as the controller lists them.
            return State("elog", _elog.AsEnumerable().Reverse().Select(e => Item("elog-message-li", $"/rw/elog/0/{Text(e.Sequence)}",
                ("msgtype", "3"), ("code", Text(e.Code)), ("title", e.Title))));
        }
    }

    private RwsResponse JointTarget()
    {
        Joints j = Twin.Arm.Joints;
        return State("motionsystem", Item("ms-jointtarget", "ROB_1",
            ("rax_1", Text(j.J1)), ("rax_2", Text(j.J2)), ("rax_3", Text(j.J3)), ("rax_4", Text(j.J4)), ("rax_5", Text(j.J5)), ("rax_6", Text(j.J6))));
    }

    private RwsResponse RobTarget()
    {
        Pose tcp = Twin.Arm.Tcp;
        Rotation r = tcp.Rotation;
        return State("motionsystem", Item("ms-robtargets", "ROB_1",
            ("x", Text(tcp.Position.X)), ("y", Text(tcp.Position.Y)), ("z", Text(tcp.Position.Z)),
            ("q1", Text(r.W)), ("q2", Text(r.X)), ("q3", Text(r.Y)), ("q4", Text(r.Z))));
    }

    private RwsResponse Signal(string name, bool get, IReadOnlyDictionary<string, string> form)
    {
        if (Twin.Signal(name) is not { } signal)
        {
            return Error(404, "Not Found", null, $"The IO configuration has no signal \"{name}\".");
        }
        bool digital = signal.Bank[0] == 'd';
        if (get)
        {
            return State("iosystem", Item("ios-signal-li", name, ("name", name), ("type", signal.Bank.ToUpperInvariant()), ("lvalue", Text(SignalValue(signal)))));
        }
        double set = double.Parse(form["lvalue"], NumberStyles.Float, CultureInfo.InvariantCulture);
        if (digital)
        {
            if (set is not (0 or 1))
            {
                return Error(400, "Bad Request", null, $"A digital signal is 0 or 1, not {Text(set)}.");
            }
            Twin.SetBit(signal.Bank, signal.Index, set == 1);
        }
        else
        {
            Twin.SetNumber(signal.Bank, signal.Index, set);
        }
        return RwsResponse.NoContent();
    }

    private bool HoldsMastership(string session)
    {
        lock (_gate)
        {
            return _master == session && MastershipHeldBy is null;
        }
    }

    private string? HeldByOther(string session)
    {
        lock (_gate)
        {
            return MastershipHeldBy ?? (_master is not null && _master != session ? "another Robot Web Services client" : null);
        }
    }

    private string HolderText() => HeldByOther("") is { } holder ? $" (held by {holder})" : "";

    private static string Text(double value) => value.ToString("R", CultureInfo.InvariantCulture);
}

using System.Globalization;

namespace Machina;

/// <summary>The controller's resources (ABB, Application manual Robot Web Services 3HAC050973-001; see docs/rws.md).</summary>
internal sealed partial class RwsClient
{
    /// <summary>The operating mode: AUTO, MANR (manual, reduced speed), MANF (manual, full speed), or a change in progress.</summary>
    public async Task<string> GetOperationModeAsync(CancellationToken cancellationToken = default) =>
        RwsXhtml.Value(await GetAsync("/rw/panel/opmode", "read the operating mode", cancellationToken).ConfigureAwait(false), "opmode");

    /// <summary>The controller state: motoron, motoroff, guardstop, emergencystop, ...</summary>
    public async Task<string> GetControllerStateAsync(CancellationToken cancellationToken = default) =>
        RwsXhtml.Value(await GetAsync("/rw/panel/ctrlstate", "read the controller state", cancellationToken).ConfigureAwait(false), "ctrlstate");

    /// <summary>The speed ratio (the FlexPendant's speed override), 0 to 100.</summary>
    public async Task<int> GetSpeedRatioAsync(CancellationToken cancellationToken = default)
    {
        string text = RwsXhtml.Value(await GetAsync("/rw/panel/speedratio", "read the speed ratio", cancellationToken).ConfigureAwait(false), "speedratio");
        return (int)Math.Round(RwsXhtml.Number(text, "speed ratio"));
    }

    /// <summary>Sets the speed ratio, 0 to 100 (automatic mode only).</summary>
    public Task SetSpeedRatioAsync(int percent, CancellationToken cancellationToken = default)
    {
        ArgumentOutOfRangeException.ThrowIfNegative(percent);
        ArgumentOutOfRangeException.ThrowIfGreaterThan(percent, 100);
        return PostAsync("/rw/panel/speedratio?action=setspeedratio", $"set the speed ratio to {percent} %", cancellationToken,
            ("speed-ratio", percent.ToString(CultureInfo.InvariantCulture)));
    }

    /// <summary>RAPID execution: running or stopped.</summary>
    public async Task<string> GetExecutionStateAsync(CancellationToken cancellationToken = default) =>
        RwsXhtml.Value(await GetAsync("/rw/rapid/execution", "read the RAPID execution state", cancellationToken).ConfigureAwait(false), "ctrlexecstate");

    /// <summary>The names of the RAPID tasks.</summary>
    public async Task<IReadOnlyList<string>> GetTasksAsync(CancellationToken cancellationToken = default)
    {
        string text = await GetAsync("/rw/rapid/tasks", "list the RAPID tasks", cancellationToken).ConfigureAwait(false);
        return [.. RwsXhtml.Items(text).Select(i => i.Values.GetValueOrDefault("name")).OfType<string>()];
    }

    /// <summary>Requests mastership of every domain (configuration, motion, RAPID).</summary>
    public Task RequestMastershipAsync(CancellationToken cancellationToken = default) =>
        PostAsync("/rw/mastership?action=request", "get mastership of the controller", cancellationToken);

    /// <summary>Releases mastership of every domain.</summary>
    public Task ReleaseMastershipAsync(CancellationToken cancellationToken = default) =>
        PostAsync("/rw/mastership?action=release", "release mastership of the controller", cancellationToken);

    /// <summary>Writes <paramref name="text"/> as the file <paramref name="path"/> on the controller (e.g. <c>$HOME/machina.mod</c>), replacing it.</summary>
    public Task UploadFileAsync(string path, string text, CancellationToken cancellationToken = default) =>
        PutAsync("/fileservice/" + path, text, $"upload {path}", cancellationToken);

    /// <summary>Loads the module file <paramref name="path"/> into <paramref name="task"/> (replacing a module of the same name when asked).</summary>
    public Task LoadModuleAsync(string task, string path, bool replace = true, CancellationToken cancellationToken = default) =>
        PostAsync($"/rw/rapid/tasks/{Uri.EscapeDataString(task)}?action=loadmod", $"load {path} into the task {task}", cancellationToken,
            ("modulepath", path), ("replace", replace ? "true" : "false"));

    /// <summary>Moves the program pointer of every task to main.</summary>
    public Task ResetProgramPointerAsync(CancellationToken cancellationToken = default) =>
        PostAsync("/rw/rapid/execution?action=resetpp", "reset the program pointer to main", cancellationToken);

    /// <summary>Starts RAPID execution of every normal task, continuously, from the program pointer.</summary>
    public Task StartAsync(CancellationToken cancellationToken = default) =>
        PostAsync("/rw/rapid/execution?action=start", "start RAPID execution", cancellationToken,
            ("regain", "continue"), ("execmode", "continue"), ("cycle", "forever"), ("condition", "none"), ("stopatbp", "disabled"), ("alltaskbytsp", "false"));

    /// <summary>Stops RAPID execution of every normal task.</summary>
    public Task StopAsync(CancellationToken cancellationToken = default) =>
        PostAsync("/rw/rapid/execution?action=stop", "stop RAPID execution", cancellationToken, ("stopmode", "stop"), ("usetsp", "normal"));

    /// <summary>The messages of the event log's common domain (0), newest first: code and title.</summary>
    public async Task<IReadOnlyList<(int Code, string Title)>> GetEventLogAsync(CancellationToken cancellationToken = default)
    {
        string text = await GetAsync("/rw/elog/0?lang=en", "read the event log", cancellationToken).ConfigureAwait(false);
        return [.. RwsXhtml.Items(text).Where(i => i.Values.ContainsKey("code")).Select(i => (
            int.TryParse(i.Values["code"], NumberStyles.Integer, CultureInfo.InvariantCulture, out int code) ? code : 0,
            i.Values.GetValueOrDefault("title") ?? ""))];
    }

    /// <summary>The joints of ROB_1 in degrees.</summary>
    public async Task<Joints> GetJointTargetAsync(CancellationToken cancellationToken = default)
    {
        string text = await GetAsync("/rw/motionsystem/mechunits/ROB_1/jointtarget", "read the joints", cancellationToken).ConfigureAwait(false);
        double J(int i) => RwsXhtml.Number(RwsXhtml.Value(text, "rax_" + i.ToString(CultureInfo.InvariantCulture)), "joint");
        return new Joints(J(1), J(2), J(3), J(4), J(5), J(6));
    }

    /// <summary>The TCP of ROB_1 (position in mm, orientation as a quaternion q1..q4) in the base frame.</summary>
    public async Task<(Vector Position, double[] Quaternion)> GetRobTargetAsync(CancellationToken cancellationToken = default)
    {
        string text = await GetAsync("/rw/motionsystem/mechunits/ROB_1/robtarget?coordinate=Base", "read the TCP", cancellationToken).ConfigureAwait(false);
        double V(string name) => RwsXhtml.Number(RwsXhtml.Value(text, name), name);
        return (new Vector(V("x"), V("y"), V("z")), [V("q1"), V("q2"), V("q3"), V("q4")]);
    }

    /// <summary>The value of RAPID data <paramref name="symbol"/> of <paramref name="module"/> in <paramref name="task"/>, as RAPID text.</summary>
    public async Task<string> GetSymbolAsync(string task, string module, string symbol, CancellationToken cancellationToken = default) =>
        RwsXhtml.Value(await GetAsync(SymbolPath(task, module, symbol), $"read {task}/{module}/{symbol}", cancellationToken).ConfigureAwait(false), "value");

    /// <summary>Sets RAPID data <paramref name="symbol"/> to <paramref name="value"/> (RAPID text, e.g. <c>5</c>, <c>TRUE</c>, <c>"text"</c>).</summary>
    public Task SetSymbolAsync(string task, string module, string symbol, string value, CancellationToken cancellationToken = default) =>
        PostAsync(SymbolPath(task, module, symbol) + "?action=set", $"set {task}/{module}/{symbol} to {value}", cancellationToken, ("value", value));

    /// <summary>The logical value of IO signal <paramref name="signal"/> (its name, or network/device/name).</summary>
    public async Task<double> GetSignalAsync(string signal, CancellationToken cancellationToken = default)
    {
        string text = await GetAsync("/rw/iosystem/signals/" + signal, $"read the signal {signal}", cancellationToken).ConfigureAwait(false);
        return RwsXhtml.Number(RwsXhtml.Value(text, "lvalue"), "signal value");
    }

    /// <summary>Sets IO signal <paramref name="signal"/> to <paramref name="value"/>.</summary>
    public Task SetSignalAsync(string signal, double value, CancellationToken cancellationToken = default) =>
        PostAsync($"/rw/iosystem/signals/{signal}?action=set", $"set the signal {signal}", cancellationToken,
            ("lvalue", value.ToString(CultureInfo.InvariantCulture)));

    private static string SymbolPath(string task, string module, string symbol) =>
        $"/rw/rapid/symbol/data/RAPID/{Uri.EscapeDataString(task)}/{Uri.EscapeDataString(module)}/{Uri.EscapeDataString(symbol)}";
}

using System.Net;
using Machina.Cli.Simulation;
using Machina.Cli.Twins;

namespace Machina.Cli.Commands;

/// <summary><c>machina sim</c>: a standalone virtual controller until Ctrl+C, logging what it receives.</summary>
internal static partial class SimCommand
{
    /// <summary>The port the ABB driver listens on by default, and so the default here.</summary>
    internal const int DefaultPort = 7000;

    /// <summary>Every option of the command (a loaded run refuses those its twin does not read); before <see cref="Command"/>, which reads it.</summary>
    private static readonly string[] AllOptions = ["--port", "--bind", "--speed-factor", "--model", "--load", "--rws-port", "--signal", "--eio", "--home", "--task-type", "--cycle", "--select"];

    internal static readonly CliCommand Command = new(
        "sim",
        "Start a virtual robot controller to try any Machina host without a robot",
        $"""
        Usage: machina sim abb|ur|kuka [--port P] [--bind ADDRESS] [--speed-factor F] [--model M]
               machina sim abb|kuka --load PROGRAM [--model M]
               machina sim kuka --load PROGRAM [--select NAME|none]
               machina sim abb --load PROGRAM [--eio EIO.cfg] [--signal [TYPE:]NAME[=VALUE]]... [--rws-port N] [--home DIR]
                               [--task-type TASK=NORMAL|STATIC|SEMISTATIC]... [--cycle once|forever]

        Starts a virtual controller that speaks the same protocol as Machina's driver on a real controller, and runs until
        Ctrl+C. Any Machina host can connect to it: this tool (machina run --host), the original Machina.NET, a Grasshopper
        definition, your own script. It tells what the controller does: connections, the driver program starting and
        stopping, each request it accepts (its own reading of the instruction), where the robot is after the actions it
        finishes, output changes, pendant messages and errors.
        Available in this build: {VirtualControllers.AvailableNames}.

        Options:
          --port P          the port hosts connect to (default {DefaultPort}; 0 picks a free one). ABB and KUKA: the driver's port,
                            P + 1 the monitor's; UR: the script port, P + 1 RTDE and P + 2 the dashboard, ready to run.
                            Without --port a UR stands in for URSim: it listens where a UR does (primary 30001, secondary
                            30002, real-time 30003, RTDE 30004, dashboard 29999) and starts powered off, as URSim does:
                            send "power on" and "brake release" to the dashboard before a program runs
          --bind ADDRESS    the address to listen on (default 127.0.0.1, this computer only; 0.0.0.0 for every network)
          --speed-factor F  how much faster than real time the robot moves (default 1; 10 is ten times faster)
          --model M         move like this arm, e.g. "IRB 120" (joints and pose then follow each other)
          --rws-port N      abb: serve Robot Web Services (RWS 1.0, digest log-on "Default User"/"robotics") on port N (default 0:
                            a free port, named in the log), in front of the controller's RAPID tasks: "machina drivers abb
                            --install --host 127.0.0.1 --rws-port N" and RWS clients work against it
          --home DIR        abb: the folder that is the controller's HOME: (RAPID's Open "HOME:/f", with TEMP: and RAMDISK: as
                            folders in it) and RWS's /fileservice/$HOME: one store, so a file uploaded through RWS is what a
                            program opens and the other way round (default: a new temporary folder, named in the log)
          --quiet           tell only connections, pendant messages, outputs and errors, not every request and action
          --load [TASK=]PROGRAM
                            abb: load a RAPID program (.mod, .sys, .pgf or a folder: its .sys then its .mod files) into a task
                            and run its main in real time, as a controller would, telling its pendant messages, until every
                            task ends or Ctrl+C. Repeat it for several tasks (--load T_ROB1=driver.mod --load T_MON=monitor.mod):
                            T_ROB1 moves the arm, the others run in the background, PERS data are shared; without TASK= the
                            program goes to T_ROB1. With --rws-port, RWS is served in front of the tasks as without --load
          --eio FILE        abb --load: the signals of a controller's IO configuration file (EIO.cfg, e.g. from a backup's
                            SYSPAR folder: each EIO_SIGNAL's -Name, -SignalType DI/DO/AI/AO/GI/GO and -Default), beside the board's
          --signal [TYPE:]NAME[=VALUE]
                            abb --load: a signal of the IO configuration and its value at the start (default 0). The board's
                            DO_1…DO_16, DI_1…DI_16, AO_1…AO_4, AI_1…AI_4 are always there; another name needs its TYPE
                            (di, do, ai or ao), e.g. --signal di:signalRobotEStop=0 --signal DI_1=1. Repeatable
                            kuka: run a compiled KRL program (a .src with its .dat, or a folder) on the KRL twin in real
                            time and list each step it makes, then stop (exit code 1 when the controller stops it)
          --select NAME|none
                            kuka --load: the program the robot interpreter runs (default: the first .src's first routine),
                            or none: no program selected ($PRO_STATE1 #P_FREE) until the folder's submit program (sps.sub)
                            selects one with CWRITE($CMD, …, "RUN /R1/NAME()")
          --task-type TASK=NORMAL|STATIC|SEMISTATIC
                            abb --load: the task's Type in the controller's system parameters (default NORMAL). A static or
                            semistatic task runs its main for ever: started again each time it ends, until an error stops it.
                            Repeatable
          --cycle once|forever
                            abb --load: the run mode of the normal tasks: once (single cycle, the default: main runs once) or
                            forever (continuous: main starts again each time it ends)

        Example:
          machina sim abb --port 7000
          (in another terminal) machina run square.machina --brand abb --host 127.0.0.1 --port 7000
        """,
        Options: AllOptions,
        Flags: ["--quiet"],
        RunAsync);

    /// <summary>The options that only a program run with --load uses (refused without it, never ignored).</summary>
    private static readonly string[] LoadOnlyOptions = ["--signal", "--eio", "--task-type", "--cycle", "--select"];

    /// <summary>Refuses an option that <paramref name="twin"/>'s loaded run would not read, and a second --load where it runs one program.</summary>
    private static void RefuseWhatALoadedRunIgnores(CliArgs args, Twins.ITwinProgram twin)
    {
        if (!twin.LoadsSeveral && args.Values("--load").Count > 1)
        {
            throw new UsageException($"{twin.Brand.DisplayName} --load runs one program (a file or a folder); --load was given {args.Values("--load").Count} times.");
        }
        if (AllOptions.FirstOrDefault(o => o is not "--load" and not "--model" && args.Value(o) is not null && !twin.LoadOptions.Contains(o)) is { } ignored)
        {
            throw new UsageException($"{ignored} does nothing when {twin.Brand.DisplayName} runs a loaded program (--load); leave it out.");
        }
    }

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        RobotType brand = Brands.Parse(args.Single("a brand (abb, ur or kuka)"), [.. Brands.Online.Where(Machina.Simulation.VirtualControllerRegistry.Has)], "sim");
        // Without --port, a brand whose vendor has its own simulator (UR: URSim) listens where that simulator does.
        IReadOnlyList<(string Name, int Port)>? vendorPorts = args.Value("--port") is null ? Machina.Simulation.VirtualControllerRegistry.VendorPorts(brand) : null;
        bool vendorLayout = vendorPorts is not null;
        int port = vendorPorts is not null ? vendorPorts[0].Port : args.Port("--port", DefaultPort, allowZero: true);
        string bindText = args.Value("--bind") ?? "127.0.0.1";
        if (!IPAddress.TryParse(bindText, out IPAddress? bind))
        {
            throw new UsageException($"--bind needs an IP address of this computer such as 127.0.0.1 or 0.0.0.0, not \"{bindText}\".");
        }
        double speed = args.Positive("--speed-factor", 1);
        if (args.Value("--home") is not null && !Machina.Simulation.VirtualControllerRegistry.HasHome(brand))
        {
            string having = string.Join(" or ", Machina.Simulation.VirtualControllerRegistry.WithMassMemory.Select(b => "a virtual " + b.DisplayName));
            throw new UsageException($"--home is the mass memory of {having} (RAPID's HOME:), not of {Brands.Name(brand)}.");
        }
        if (args.Value("--load") is null && LoadOnlyOptions.FirstOrDefault(o => args.Value(o) is not null) is { } loadOnly)
        {
            throw new UsageException($"{loadOnly} sets up a program that --load runs; without --load it would do nothing. Add --load PROGRAM or leave {loadOnly} out.");
        }
        // Options are checked before --load takes over: a mistyped one is an error there too, never ignored.
        if (args.Value("--load") is not null)
        {
            if (TwinPrograms.Loading.FirstOrDefault(t => t.Brand.Type == brand) is not { RunLoaded: { } runLoaded } twin)
            {
                throw new UsageException($"--load runs compiled programs on {LoadingNames()}, not on {Brands.Name(brand)}.");
            }
            RefuseWhatALoadedRunIgnores(args, twin);
            return await runLoaded(args, Brands.Model(args.Value("--model") ?? twin.Brand.DefaultModel, brand)!, bind, context).ConfigureAwait(false);
        }
        RobotModel? model = Brands.Model(args.Value("--model"), brand);
        bool quiet = args.Has("--quiet");

        var gate = new Lock();
        void Log(string line)
        {
            lock (gate)
            {
                context.Stdout.WriteLine(line);
                context.Stdout.Flush();
            }
        }

        // ABB and KUKA listen where asked themselves; a UR's ports are relayed (its layout is not the compact one of its controller).
        bool direct = !vendorLayout && Machina.Simulation.VirtualControllerRegistry.ListensWhereAsked(brand);
        bool stopping = false;
        var settings = new VirtualControllerOptions(speed, model, vendorLayout, Home(args, context))
        {
            Listen = direct ? (bind, port) : null,
            ConnectionSeen = (name, who, connected) =>
            {
                if (connected || !Volatile.Read(ref stopping))
                {
                    Log($"{who} {(connected ? "connected" : "disconnected")} ({name})");
                }
            },
        };
        RunningController started;
        try
        {
            started = await VirtualControllers.StartAsync(brand, settings, context.Cancellation).ConfigureAwait(false);
        }
        catch (System.Net.Sockets.SocketException ex)
        {
            throw TcpRelay.ListenError(ex, bind, port, [0, 1]);
        }
        await using RunningController controller = started;
        RelayRoute[] routes = vendorPorts is not null ? VendorRoutes(controller, vendorPorts) : controller.CompactRoutes;
        await using TcpRelay? relay = direct ? null : TcpRelay.Start(bind, port, routes, Log);
        int firstPort = relay?.Port ?? controller.Port;
        int[] ports = relay?.Ports ?? controller.Ports;
        // The first line says "listening" and where (scripts and tests read it). ABB and KUKA listen themselves, so their program
        // may reach the pendant before that line: what the controller does until then is held and told after it.
        var held = new List<string>();
        bool announced = false;
        void Activity(string line)
        {
            lock (held)
            {
                if (!announced)
                {
                    held.Add(line);
                    return;
                }
            }
            Log(line);
        }
        await using ControllerActivity activity = ControllerActivity.Start(controller, Activity, context.Time, quiet);
        // RWS is named after the controller's first line, which says "listening" and where.
        var rwsLines = new List<string>();
        await using IAsyncDisposable? rws = SimWebServices.Start(controller, bind, () => args.Port("--rws-port", 0, allowZero: true), DefaultPort + 100, Log, rwsLines.Add);
        Log($"Virtual {brand} controller listening on {bind}:{firstPort} {Ports(routes, ports)}" +
            $", {Num(speed)}x real time{(model is null ? "" : $", moving like an {model}")}. Press Ctrl+C to stop.");
        rwsLines.ForEach(Log);
        Log($"Connect a Machina host to {(bind.Equals(IPAddress.Any) ? "this computer's address" : bind.ToString())} port {firstPort}, e.g.: " +
            $"machina run PROGRAM --brand {Brands.Name(brand)} --host {(bind.Equals(IPAddress.Any) ? "127.0.0.1" : bind.ToString())} --port {firstPort}");
        if (vendorLayout && Machina.Simulation.VirtualControllerRegistry.VendorSimulatorNote(brand) is { } note)
        {
            Log(note);
        }
        lock (held)
        {
            held.ForEach(Log);
            announced = true;
        }
        context.Ready?.Invoke($"{bind}:{firstPort}");
        try
        {
            await Task.Delay(Timeout.Infinite, context.Cancellation).ConfigureAwait(false);
        }
        catch (OperationCanceledException)
        {
        }
        activity.Flush();
        Volatile.Write(ref stopping, true); // the hosts the controller's stop disconnects are not told, as the relay's were not
        Log($"Stopping: {controller.Summary()}.");
        return ExitCodes.Ok;
    }

    /// <summary>The folder <c>--home DIR</c> names (made when missing), or null without it.</summary>
    internal static string? Home(CliArgs args, CliContext context)
    {
        if (args.Value("--home") is not { } home)
        {
            return null;
        }
        string full = context.FullPath(home);
        try
        {
            Directory.CreateDirectory(full);
        }
        catch (Exception ex) when (ex is IOException or UnauthorizedAccessException or ArgumentException or NotSupportedException)
        {
            throw new CliException($"--home {home}: cannot use that folder: {ex.Message}");
        }
        return full;
    }

    /// <summary>Every port named for what it is, e.g. "(script port; RTDE on 7001, dashboard on 7002)".</summary>
    internal static string Ports(IReadOnlyList<RelayRoute> routes, IReadOnlyList<int> ports)
    {
        string others = string.Join(", ", routes.Skip(1).Select((route, i) =>
            $"{route.Name} on {ports[i + 1].ToString(System.Globalization.CultureInfo.InvariantCulture)}"));
        return $"({routes[0].Name} port{(others.Length > 0 ? "; " + others : "")})";
    }

    /// <summary>The vendor layout's routes to the controller's own ports (UR: its compact script port is not relayed, the client interfaces take scripts).</summary>
    private static RelayRoute[] VendorRoutes(RunningController controller, IReadOnlyList<(string Name, int Port)> layout) =>
        [.. layout.Select(p => new RelayRoute(p.Port - layout[0].Port, controller.Ports[Array.IndexOf(controller.PortNames, p.Name)], p.Name))];

    /// <summary>The brands whose twin loads programs, with their language, e.g. "abb (RAPID) and kuka (KRL)".</summary>
    private static string LoadingNames()
    {
        string[] names = [.. TwinPrograms.Loading.Select(t => $"{t.Brand.Name} ({t.Language})")];
        return names.Length < 2 ? string.Concat(names) : string.Join(", ", names[..^1]) + " and " + names[^1];
    }

    private static string Num(double value) => value.ToString("0.###", System.Globalization.CultureInfo.InvariantCulture);
}

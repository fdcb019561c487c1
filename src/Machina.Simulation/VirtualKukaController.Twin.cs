using System.Globalization;
using System.Net.Sockets;
using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>The EthernetKRL channel of the driver, as its configuration file is named.</summary>
    internal const string DriverChannel = "machina_kuka_server";

    /// <summary>The EthernetKRL channel of the monitor, as its configuration file is named.</summary>
    internal const string MonitorChannel = "machina_kuka_monitor";

    /// <summary>
    /// The driver's $ADVANCE on the virtual KUKA: 0 (<c>machina drivers kuka</c> can write it), what the twin does anyway (its
    /// motion runs in the robot interpreter's thread): an acknowledged motion has arrived.
    /// </summary>
    private const string DefaultAdvance = "0";

    /// <summary>How often the submit interpreter calls the monitor (sps.sub's loop); its $TIMER decides when a report goes out.</summary>
    internal static readonly TimeSpan SubmitCycle = TimeSpan.FromMilliseconds(4);

    /// <summary>How many steps of the arm's trace the controller keeps: a stream of millions of moves must not keep every pose.</summary>
    internal const int MaxTraceSteps = 10_000;

    /// <summary>The KRL controller that runs Machina's driver and monitor, once started (null before).</summary>
    internal KrlTwinController? Twin { get; private set; }

    /// <summary>Cancels the driver's current run for a program reset; null between runs.</summary>
    private CancellationTokenSource? _driverRun;

    /// <summary>Set by a restart that loses the progress: the driver's next run starts with its progress at 0.</summary>
    private bool _forgetProgress;

    /// <summary>
    /// Loads drivers/kuka as <c>machina drivers kuka</c> writes them (driver channel on <see cref="Port"/>, monitor on port + 1),
    /// starts the driver on the robot interpreter and the monitor in the submit interpreter; the channels accept on the sockets
    /// bound here.
    /// </summary>
    private void StartTwin(TcpListener driver, TcpListener monitor, CancellationToken token)
    {
        _twinToken = token;
        var twin = new KrlTwinController(new KrlTwinOptions
        {
            Model = Model ?? RobotModels.Get("KR 6 R900 sixx"),
            StartJoints = base.State.Joints, // the options' starting joints (Observe keeps them until the twin is made)
            Time = TwinScaledTime.Of(Clock, _options.SpeedFactor),
            RealTime = !_options.InstantExecution,
            Seam = this,
            MaxTrace = MaxTraceSteps,
        });
        // The shipped files with their placeholders filled, as an installer writes them: driver on Port, monitor on Port + 1.
        string Fill(string file, int port) => DriverFiles.Fill(DriverFiles.Read(file),
            ("HOSTNAME", "127.0.0.1"), ("PORT", port.ToString(CultureInfo.InvariantCulture)), ("ADVANCE", DefaultAdvance));
        twin.AddEkiConfiguration(DriverChannel, Fill(DriverChannel + ".xml", Port));
        twin.AddEkiConfiguration(MonitorChannel, Fill(MonitorChannel + ".xml", MonitorPort));
        twin.Load([.. new[] { "machina_kuka_driver.src", "machina_kuka_driver.dat", "machina_kuka_monitor.src", "machina_kuka_monitor.dat" }
            .Select(name => (name, AsDriverVersion(Fill(name, Port), _options.DriverVersion)))]);
        // The monitor's first rate, as if its data list had been edited before loading (the host sends its own with MON).
        twin.Modules[MonitorChannel].Data["mon_ms"].Value = (int)Math.Clamp(_options.MonitorPeriod.TotalMilliseconds, 1, 3_600_000);
        twin.Pendant.Logged += line =>
        {
            if (line.StartsWith("EthernetKRL", StringComparison.Ordinal) || line.StartsWith("Submit interpreter stopped", StringComparison.Ordinal))
            {
                RecordError(line);
            }
            else
            {
                Pendant(line);
            }
        };
        twin.Reserve(DriverChannel, driver);
        twin.Reserve(MonitorChannel, monitor);
        Twin = twin;
        Run(_ => RunTwinAsync(twin, token));
    }

    /// <summary>The driver on the robot interpreter and the monitor in the submit interpreter, each on a thread of its own, until the controller stops.</summary>
    private async Task RunTwinAsync(KrlTwinController twin, CancellationToken token)
    {
        Task program = Task.Factory.StartNew(() => RunDriver(twin, token), CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        Task submit = Task.Factory.StartNew(() => twin.RunSubmit("machina_kuka_monitor", SubmitCycle, token),
            CancellationToken.None, TaskCreationOptions.LongRunning, TaskScheduler.Default);
        try
        {
            await Task.WhenAll(program, submit).ConfigureAwait(false);
        }
        finally
        {
            twin.Dispose();
        }
    }

    /// <summary>
    /// The driver on the robot interpreter until the controller stops; after a program reset (<see cref="ResetDriverProgram"/>)
    /// it starts again from the top, its EthernetKRL channel (ENVIRONMENT Program) cleared as the reset clears it.
    /// </summary>
    private void RunDriver(KrlTwinController twin, CancellationToken token)
    {
        while (!token.IsCancellationRequested)
        {
            using var run = CancellationTokenSource.CreateLinkedTokenSource(token);
            lock (Gate)
            {
                _driverRun = run;
            }
            KrlProgramState state = twin.Run("machina_kuka_driver", run.Token);
            lock (Gate)
            {
                _driverRun = null;
            }
            if (token.IsCancellationRequested)
            {
                return;
            }
            if (!run.IsCancellationRequested)
            {
                EndDriver(state, twin.Error);
                return;
            }
            twin.ClearEki(DriverChannel);
            if (TakeForgetProgress())
            {
                // What the driver ran with nobody connected is logged before its progress goes: the log keeps every run.
                KrlModule driver = twin.Modules["machina_kuka_driver"];
                SettleRestart(KrlValues.ToInt(driver.Data["last_executed"].Value));
                driver.Data["last_executed"].Value = 0;
                driver.Data["last_received"].Value = 0;
            }
            else
            {
                ForgetDropped();
            }
            Pendant("program reset: machina_kuka_driver starts again from the top");
        }
    }

    private bool TakeForgetProgress()
    {
        lock (Gate)
        {
            bool forget = _forgetProgress;
            _forgetProgress = false;
            return forget;
        }
    }

    /// <summary>
    /// The driver program ended without a reset (a runtime error, a HALT after a failure it reported): it no longer opens its
    /// channel, so the controller says so on the pendant and stops listening on the driver port, as a KR C4 whose channel is
    /// closed refuses the connection. A host that connects again is told at once rather than waiting for a state that never comes.
    /// </summary>
    private void EndDriver(KrlProgramState state, string? error)
    {
        if (state == KrlProgramState.Failed)
        {
            RecordError(error ?? "the driver stopped");
        }
        try
        {
            _driverListener?.Stop();
        }
        catch (SocketException e)
        {
            RecordError("stopping the driver port: " + e.Message);
        }
        // After the port closed: whoever reads this line finds connections refused.
        Pendant($"machina_kuka_driver ended ({state.ToString().ToLowerInvariant()}): the driver port no longer accepts connections; restart the virtual controller to serve again (on a KR C4: reset and start the program)");
    }

    /// <summary>
    /// A program reset (the fault plan's RestartLosingBuffer): the driver stops where it is (between two statements) and runs
    /// again from its first line. Its ring and progress are data-list variables, which keep their values over a reset; the
    /// driver empties the ring when it starts and keeps the last executed id, so the host learns which actions ran (their
    /// acknowledgements may have been lost with the connection) and sends again only those the ring lost.
    /// </summary>
    private void ResetDriverProgram()
    {
        lock (Gate)
        {
            _driverRun?.Cancel();
            _heldTwinAcknowledgement = null;
        }
    }

    /// <summary>The robot now (<see cref="VirtualController{TState}.State"/>): where the twin's arm is, with the driver's settings and the outputs.</summary>
    private protected override VirtualKukaState Observe(VirtualKukaState kept) => Twin is { } twin ? TwinState(twin, kept) : kept;

    private static VirtualKukaState TwinState(KrlTwinController twin, VirtualKukaState basis)
    {
        var seen = new TwinObservation();
        seen.DigitalBank(twin.Io, "$OUT", "", 1);
        seen.AnalogBank(twin.Io, "$ANOUT", 1);
        var vel = (KrlStructValue)twin.Motion.Vel.Value;
        var apo = (KrlStructValue)twin.Motion.Apo.Value;
        return seen.Apply(basis, twin.Arm, twin.Arm.Joints, twin.Arm.ToolCenter) with
        {
            Speed = vel.Real(0) * 1000,
            Zone = apo.Number("CDIS"),
        };
    }
}

using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>How many steps of the arm's trace the controller keeps: a stream of millions of moves must not keep every pose.</summary>
    internal const int MaxTraceSteps = 10_000;

    /// <summary>The URScript controller that runs what arrives on the script ports.</summary>
    internal UrTwinController Twin { get; }

    /// <summary>Makes the interpreter that runs the scripts, starting at the controller's starting joints.</summary>
    private UrTwinController CreateTwin()
    {
        var twin = new UrTwinController(new UrTwinOptions
        {
            Model = Model ?? RobotModels.Get("UR5e"),
            Seam = this,
            MaxTrace = MaxTraceSteps,
            StartJoints = base.State.Joints, // the options' starting joints (Observe keeps them until the twin is made)
            Time = TwinScaledTime.Of(Clock, _options.SpeedFactor),
            RealTime = !_options.InstantExecution,
            Route = _options.OutboundRoute,
            StartRefusal = StartRefusal,
            HeldBySafety = () => SafetyStatus != Normal,
        });
        twin.ProgramReceived += program =>
        {
            lock (Gate)
            {
                _runtimeException = null; // a new program: the error of the last one is history
                _scripts.Add(program);
                if (_scripts.Count > MaxKeptTexts)
                {
                    _scripts.RemoveAt(0);
                }
            }
        };
        twin.Pendant.Logged += line =>
        {
            if (line.StartsWith("Compile error", StringComparison.Ordinal) || line.StartsWith("Runtime error", StringComparison.Ordinal))
            {
                RecordError(line);
            }
            else if (line.StartsWith(NotReadyPrefix, StringComparison.Ordinal))
            {
                RecordError(line);
                SendToStateClients(() => VirtualUrClientPackages.Text(Timestamp, line));
            }
            else
            {
                Pendant(line);
                SendToStateClients(() => VirtualUrClientPackages.Text(Timestamp, line));
            }
        };
        twin.StateChanged += WakeRtde;
        twin.ProtectiveStopRequested += () => ProtectiveStop();
        twin.RuntimeError += SendTwinRuntimeError;
        return twin;
    }

    /// <summary>
    /// Feeds what one script connection sends to the interpreter, which starts each program as soon as it is complete; the
    /// connection has its own intake, so a client's unfinished text never joins another client's program. On the primary
    /// interface (<paramref name="primary"/>) the primary commands that are not URScript are taken out first and carried out
    /// before the rest of the text they came with is received. Awaited throughout: a stop or a new program holds no thread while
    /// the program it ends winds down.
    /// </summary>
    private async Task FeedTwinAsync(NetworkStream stream, UrTwinController twin, CancellationToken token, bool primary = false)
    {
        List<string> taken = [];
        VirtualUrPrimaryCommands? commands = primary ? new VirtualUrPrimaryCommands(taken.Add) : null;
        var intake = new UrScriptIntake();
        var bytes = new byte[64 * 1024];
        while (true)
        {
            int n = await stream.ReadAsync(bytes, token).ConfigureAwait(false);
            if (n == 0)
            {
                return;
            }
            // A UR reads its script ports as single-byte text; Latin-1 keeps every byte.
            string text = Encoding.Latin1.GetString(bytes, 0, n);
            if (commands is not null)
            {
                text = commands.Filter(text);
                foreach (string command in taken)
                {
                    await PrimaryCommandAsync(command, token).ConfigureAwait(false);
                }
                taken.Clear();
            }
            if (text.Length > 0)
            {
                await twin.ReceiveAsync(text, intake, token).ConfigureAwait(false);
            }
        }
    }

    /// <summary>RTDE runtime_state of the interpreter: 2 playing while a program runs, 4 while it is held (paused or protective stop), else 1 stopped.</summary>
    private uint TwinRuntime(UrTwinController twin) => twin.State != UrProgramState.Running ? Stopped : TwinHeld ? Paused : Playing;

    /// <summary>The robot now (<see cref="VirtualController{TState}.State"/>): where the twin's arm is, with its outputs.</summary>
    private protected override VirtualUrState Observe(VirtualUrState kept) => Twin is null ? kept : TwinState(Twin, kept);
}

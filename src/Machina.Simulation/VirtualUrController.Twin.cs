using System.Net.Sockets;
using System.Text;
using Machina.Simulation.UrScript;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>The URScript controller that runs what arrives on the script ports (<see cref="VirtualUrControllerOptions.RunsScripts"/>), else null.</summary>
    internal UrTwinController? Twin { get; private set; }

    /// <summary>Makes the interpreter that runs the scripts, starting at the controller's starting joints.</summary>
    private void CreateTwin()
    {
        var twin = new UrTwinController(new UrTwinOptions
        {
            Model = Model!,
            StartJoints = State.Joints,
            Time = Clock,
            RealTime = !_options.InstantExecution,
        });
        twin.ProgramReceived += program =>
        {
            lock (Gate)
            {
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
            else
            {
                Pendant(line);
            }
        };
        twin.StateChanged += WakeRtde;
        twin.RuntimeError += SendTwinRuntimeError;
        Twin = twin;
    }

    /// <summary>Feeds what one script connection sends to the interpreter, which starts each program as soon as it is complete.</summary>
    private async Task FeedTwinAsync(NetworkStream stream, UrTwinController twin, CancellationToken token)
    {
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
            await Task.Run(() => twin.Receive(text), token).ConfigureAwait(false);
        }
    }

    /// <summary>RTDE runtime_state of the interpreter: 2 playing while a program runs, else 1 stopped.</summary>
    private static uint RuntimeOf(UrTwinController twin) => twin.State == UrProgramState.Running ? Playing : Stopped;
}

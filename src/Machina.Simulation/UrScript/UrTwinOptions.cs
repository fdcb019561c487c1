using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>Settings of a URScript twin controller.</summary>
internal sealed record UrTwinOptions : TwinOptions
{
    /// <summary>Settings with the virtual UR's arm: a UR5e at a common UR home, upright with the tool pointing down.</summary>
    public UrTwinOptions()
        : base(RobotModels.Get("UR5e"), new Joints(0, -90, 90, -90, -90, 0))
    {
    }

    /// <summary>
    /// How much a secondary program may do in its one controller step (statements and loop turns counted together; the Script
    /// Manual: it "must be simple enough to be executed in a single controller step"). One that does more stops there with a
    /// UR's "Runtime is too much behind" and a protective stop. The twin's bound: a UR's step is 2 ms of its processor's time,
    /// which a count of statements stands for so that the same program does the same on any machine.
    /// </summary>
    public long SecondaryStepWork { get; init; } = 10_000;

    /// <summary>
    /// How long past a <c>servoj</c>'s time t the arm goes on tracking its target when the program's thread gives no new
    /// command (the Script Manual: t is the "time where the command is controlling the robot"); then the servo has run out
    /// and the arm stands where it is. A UR's real-time thread gives the next command in the next 2 ms control step; the
    /// twin's program thread can be late by some milliseconds on a loaded machine (session 34 saw 6-10 ms), which this covers
    /// so that a servo loop that keeps calling is not stopped by the twin's own scheduling.
    /// </summary>
    public TimeSpan ServoRunOut { get; init; } = TimeSpan.FromSeconds(0.02);

    /// <summary>The seed of <c>random()</c>.</summary>
    public int RandomSeed { get; init; } = 1;

    /// <summary>Who watches the program's sockets and carries their writes (the virtual UR's fault and inspection seam), or null.</summary>
    public IUrSocketSeam? Seam { get; init; }

    /// <summary>Where <c>socket_open</c> really connects, given where the program asks (the network in between), or null.</summary>
    public Func<System.Net.DnsEndPoint, System.Net.DnsEndPoint>? Route { get; init; }

    /// <summary>How long <c>socket_open</c> tries to connect (the Script Manual says 2 s).</summary>
    public TimeSpan SocketOpenTimeout { get; init; } = TimeSpan.FromSeconds(2);

    /// <summary>
    /// True: a program that has a socket open blends too, when the next instruction has already arrived as its blended motion
    /// starts (as a UR does when its program reads ahead). False (the default): such a program's motions stop at their waypoints,
    /// since whether the next instruction has arrived depends on timing that tests cannot control. Programs without sockets always blend.
    /// </summary>
    public bool BlendWhileStreaming { get; init; }

    /// <summary>
    /// Asked before each program starts: null lets it start; a message refuses it (it does not run, the running one goes on,
    /// and the controller's <c>Error</c> and the pendant have the message). The virtual UR refuses programs while the
    /// arm is powered off or its brakes are held. Null (the default): every program that compiles starts.
    /// </summary>
    public Func<string?>? StartRefusal { get; init; }

    /// <summary>
    /// True while a safety stop holds the program (the virtual UR's protective or emergency stop): a new program that starts
    /// does not end that hold. Any other hold (a pause: the dashboard's, an RTDE watchdog's) ends with the program it held, and
    /// the new program runs, as a script sent to a paused UR does. Null: every hold is a pause.
    /// </summary>
    public Func<bool>? HeldBySafety { get; init; }
}

using System.Buffers.Binary;
using System.Net;
using System.Net.Sockets;
using System.Reflection;
using System.Text;
using Machina.Simulation;

namespace Machina.Tests.Reliability;

/// <summary>
/// UR's "can the driver run it" (issue 28): every verb of <see cref="Robot"/> with the edge values of <see cref="ExtremeValues"/>
/// (one parameter at a time) and seeded random combinations, issued as online issuing does (the brand's WhyCannotStream, the
/// cursor, WhyCannotSend). Whatever is accepted encodes and runs on the virtual UR, acknowledged, without a runtime error;
/// whatever is refused says why.
/// </summary>
public class UrDriverRulesPropertyTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);
    private const string Start = "DefineTool(\"T\", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50); PushSettings(); TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);";

    [Fact]
    public async Task UrDriverRules_EdgeAndSeededValuesOfEveryVerb_AcceptedRunOnTheVirtualUr_RefusedSayWhy()
    {
        List<(string Name, MethodInfo Verb, object?[] Args)> cases = ExtremeValues.Cases(seed: 2811, seeded: 400);

        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { Model = null, InstantExecution = true, SpeedFactor = 1e9, RequestLogCapacity = 0 });
        await controller.StartAsync();
        var brand = new UrOnline();
        var problems = new List<string>();
        int accepted = 0, refused = 0, sent = 0, wireId = 0;
        DriverLink link = await DriverLink.OpenAsync(controller);
        try
        {
            foreach ((string name, MethodInfo verb, object?[] args) in cases)
            {
                Robot bot = Robot.Create("Rules", "UR");
                bot.Do(Start);
                int before = bot.GetProgramActions().Count;
                try
                {
                    verb.Invoke(bot, args);
                }
                catch (TargetInvocationException)
                {
                    continue; // the verb refused its arguments itself (ExtremeValueTests checks how)
                }
                var cursor = new RobotCursor();
                IReadOnlyList<RobotAction> actions = bot.GetProgramActions();
                for (int i = 0; i < actions.Count; i++)
                {
                    RobotAction action = actions[i];
                    // As Robot issues online: the kind first, then the state it leads to, then the encoding of that state.
                    string? why = brand.WhyCannotStream(action);
                    var trial = new RobotCursor();
                    trial.CopyFrom(cursor);
                    why ??= trial.TryApply(action) ?? brand.WhyCannotSend(action, trial);
                    if (i < before)
                    {
                        Assert.True(why is null, $"{name}: the start {action} was refused: {why}");
                    }
                    if (why is not null)
                    {
                        refused++;
                        if (string.IsNullOrWhiteSpace(why) || why.Length < 20)
                        {
                            problems.Add($"{name}: {action} refused without a reason (\"{why}\")");
                        }
                        break; // a refused action leaves the program there
                    }
                    cursor = trial;
                    accepted++;
                    var values = new int[UrActionEncoder.MaxValues];
                    int count = UrActionEncoder.Encode(action, cursor, values);
                    // A wait for an input ends only when something sets it (or at its limit, failing): WaitForDigitalTwinTests run those.
                    if (count == 0 || i < before || action is ActionWaitDigital)
                    {
                        continue;
                    }
                    int id = ++wireId;
                    Renumber(values.AsSpan(0, count), id);
                    if (!await link.RunAsync(values[..count], id))
                    {
                        if (IsKinematic(controller.LastRuntimeException))
                        {
                            // The driver read and ran it; the UR5e arm could not go there (kinematics, not a wire rule).
                            await link.DisposeAsync();
                            link = await DriverLink.OpenAsync(controller);
                            sent++;
                            continue;
                        }
                        problems.Add($"{name}: {action} ({string.Join(' ', values[..count])}) was accepted but the virtual UR stopped: {controller.LastRuntimeException ?? string.Join(" / ", controller.Errors.TakeLast(1))}");
                        await link.DisposeAsync();
                        link = await DriverLink.OpenAsync(controller);
                    }
                    sent++;
                }
                // The settings the case left must still let the robot move (a speed that reached the wire as 0 would not).
                if (cursor.Position is Vector p && cursor.Rotation is Rotation r)
                {
                    RotationVector rv = r.ToRotationVector();
                    int id = ++wireId;
                    if (!await link.RunAsync([id, 1, UrWire.Millimetres(p.X), UrWire.Millimetres(p.Y), UrWire.Millimetres(p.Z), UrWire.Degrees(rv.X), UrWire.Degrees(rv.Y), UrWire.Degrees(rv.Z)], id))
                    {
                        if (!IsKinematic(controller.LastRuntimeException))
                        {
                                problems.Add($"{name}: a move after it stopped the virtual UR: {controller.LastRuntimeException}");
                        }
                        await link.DisposeAsync();
                        link = await DriverLink.OpenAsync(controller);
                    }
                }
            }
        }
        finally
        {
            await link.DisposeAsync();
        }

        Assert.True(problems.Count == 0, $"{problems.Count} problems:\n" + string.Join("\n", problems.Take(30)));
        Assert.InRange(cases.Count, 1_000, 100_000);
        Assert.InRange(sent, cases.Count / 10, cases.Count * 4);
        Assert.InRange(refused, cases.Count / 20, cases.Count);
        Assert.True(accepted >= sent);
    }

    /// <summary>
    /// A runtime error of the arm's kinematics (a target out of the UR5e's reach or joint limits, a path through a singularity):
    /// the virtual UR runs URScript on a real arm model, so such values stop the program as on a UR; the wire carried them. An arc
    /// (movec) starts where the arm stands, which here is where the last case left it: its three points may then define no circle.
    /// </summary>
    private static bool IsKinematic(string? error) =>
        error is not null && (error.Contains("inverse kinematics", StringComparison.Ordinal) || error.Contains("beyond its limits", StringComparison.Ordinal)
            || error.Contains("leaves the workspace", StringComparison.Ordinal) || error.Contains("singularity", StringComparison.Ordinal)
            || error.Contains("do not define a circle", StringComparison.Ordinal));

    [Theory]
    [InlineData("SpeedTo(0.0004);", "a speed of 0.0004 mm/s is 0 in its driver's 0.001 mm/s steps")]
    [InlineData("AccelerationTo(0.0001);", "an acceleration of 0.0001 mm/s² is 0 in its driver's 0.001 mm/s² steps")]
    [InlineData("WriteDigital(2147483647, true);", "UR robots have standard digital outputs 0 to 7; output 2147483647 does not exist.")]
    [InlineData("WriteDigital(2, true, true);", "UR robots have tool digital outputs 0 to 1; output 2 does not exist.")]
    [InlineData("WriteAnalog(0, 1.5);", "UR analog outputs take a value from 0 to 1")]
    [InlineData("AxesTo(0, -90, 130000, 0, 0, 0);", "a value is beyond its driver's 32-bit numbers (lengths and speeds up to ±2147483 mm, angles ±123041°, times 2147483 s)")]
    public void UrDriverRules_WhatTheDriverCannotRun_RefusedWithTheReason(string instruction, string reason)
    {
        Robot bot = Robot.Create("Rules", "UR");
        bot.Do(Start);
        var cursor = new RobotCursor();
        foreach (RobotAction a in bot.GetProgramActions())
        {
            Assert.Null(cursor.TryApply(a));
        }
        bot.Do(instruction);
        RobotAction action = bot.GetProgramActions()[^1];
        var brand = new UrOnline();

        string? why = brand.WhyCannotStream(action) ?? cursor.TryApply(action) ?? brand.WhyCannotSend(action, cursor);

        Assert.NotNull(why);
        Assert.Contains("cannot be streamed to a UR robot: ", why, StringComparison.Ordinal);
        Assert.Contains(reason, why, StringComparison.Ordinal);
        Assert.Throws<InvalidOperationException>(() => UrActionEncoder.Encode(action, cursor, new int[UrActionEncoder.MaxValues]));
    }

    /// <summary>How many integers follow an instruction's id and code (spec online §7.3).</summary>
    private static int ParametersOf(int code) => code switch
    {
        1 or 2 or 3 or 17 => 6,
        4 or 5 or 6 or 7 or 8 or 9 or 15 or 16 => 1,
        12 => 7,
        13 => 3,
        14 => 2,
        18 => 4,
        19 or 20 => 2,
        21 => 12,
        _ => throw new ArgumentOutOfRangeException(nameof(code), code, "not an instruction code of the protocol"),
    };

    /// <summary>Gives the action's last instruction <paramref name="id"/> (the one that carries the action's id), helpers keep 0.</summary>
    private static void Renumber(Span<int> values, int id)
    {
        int last = 0;
        for (int at = 0; at < values.Length; at += 2 + ParametersOf(values[at + 1]))
        {
            last = at;
            if (values[at] != 0)
            {
                values[at] = 0;
            }
        }
        values[last] = id;
    }

    /// <summary>A host's side of one driver program: the script sent, the connection back, instructions and their acknowledgements.</summary>
    private sealed class DriverLink : IAsyncDisposable
    {
        private readonly TcpListener _server;
        private readonly TcpClient _script;
        private readonly TcpClient _driver;

        private DriverLink(TcpListener server, TcpClient script, TcpClient driver) => (_server, _script, _driver) = (server, script, driver);

        public static async Task<DriverLink> OpenAsync(VirtualUrController controller)
        {
            var server = new TcpListener(IPAddress.Loopback, 0);
            server.Start();
            var script = new TcpClient();
            await script.ConnectAsync(IPAddress.Loopback, controller.Port);
            await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(UrDriverScript.For("127.0.0.1", ((IPEndPoint)server.LocalEndpoint).Port, 3)));
            TcpClient driver = await server.AcceptTcpClientAsync().WaitAsync(Timeout);
            await driver.GetStream().ReadExactlyAsync(new byte[19 * 4]).AsTask().WaitAsync(Timeout);
            return new DriverLink(server, script, driver);
        }

        /// <summary>Sends the instructions and waits for <paramref name="id"/>'s acknowledgement; false when the program stopped instead.</summary>
        public async Task<bool> RunAsync(int[] values, int id)
        {
            var bytes = new byte[values.Length * 4];
            UrWire.Write(values, bytes);
            NetworkStream stream = _driver.GetStream();
            await stream.WriteAsync(bytes);
            var ack = new byte[4];
            bool inResponse = false;   // a read's value response (-60 id value End) comes before its acknowledgement
            while (true)
            {
                int read = 0;
                while (read < 4)
                {
                    int n = await stream.ReadAsync(ack.AsMemory(read)).AsTask().WaitAsync(Timeout);
                    if (n == 0)
                    {
                        return false;
                    }
                    read += n;
                }
                int value = BinaryPrimitives.ReadInt32BigEndian(ack);
                if (inResponse)
                {
                    inResponse = value != UrWire.End;
                }
                else if (value < -1)
                {
                    inResponse = true;
                }
                else if (value == id)
                {
                    return true;
                }
            }
        }

        public ValueTask DisposeAsync()
        {
            _driver.Dispose();
            _script.Dispose();
            _server.Stop();
            return ValueTask.CompletedTask;
        }
    }
}

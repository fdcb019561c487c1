using Machina.Simulation;
using Machina.Tests.Online;

namespace Machina.Tests.Reliability;

/// <summary>
/// A representative sample of edge values issued online to each brand's virtual controller: each is refused at issue time with
/// a documented error, or executed; either way the link and the controller keep serving, and a normal move after it is
/// acknowledged and ends where it should.
/// </summary>
public class ExtremeValueOnlineTests
{
    private static readonly string Huge = new('x', 1_000_000);

    /// <summary>The sample: one per kind of edge (number overflow, denormal, infinity, int and long edges, texts).</summary>
    private static readonly (string What, Action<Robot> Issue)[] Sample =
    [
        ("MoveTo(1e308, 0, 0)", b => b.MoveTo(1e308, 0, 0)),
        ("Move(-1e308, 0, 0)", b => b.Move(-1e308, 0, 0)),
        ("MoveTo(NaN)", b => b.MoveTo(double.NaN, 0, 0)),
        ("Rotate(0, 0, 1, 1e308)", b => b.Rotate(0, 0, 1, 1e308)),
        ("AxesTo(1e308 …)", b => b.AxesTo(1e308, 0, 0, 0, 0, 0)),
        ("SpeedTo(Epsilon)", b => b.SpeedTo(double.Epsilon)),
        ("SpeedTo(1e308)", b => b.SpeedTo(1e308)),
        ("AccelerationTo(1e308)", b => b.AccelerationTo(1e308)),
        ("PrecisionTo(1e308)", b => b.PrecisionTo(1e308)),
        ("Wait(long.MaxValue)", b => b.Wait(long.MaxValue)),
        ("Wait(int.MaxValue + 1)", b => b.Wait(int.MaxValue + 1L)),
        ("WriteDigital(int.MaxValue)", b => b.WriteDigital(int.MaxValue, true)),
        ("WriteAnalog(1, 1e308)", b => b.WriteAnalog(1, 1e308)),
        ("WriteAnalog(1, -Epsilon)", b => b.WriteAnalog(1, -double.Epsilon)),
        ("WriteDigital(\"a\\\"b;\")", b => b.WriteDigital("a\"b;", true)),
        ("Message(huge)", b => b.Message(Huge)),
        ("Message(control and quotes)", b => b.Message("a\0b\r\n\"c\";\u001b é 日本")),
        ("Message(\"\")", b => b.Message("")),
        ("CustomCode(huge)", b => b.CustomCode(Huge)),
        ("ExternalAxisTo(1, 1e308)", b => b.ExternalAxisTo(1, 1e308)),
        ("DefineTool(1e308 tip)", b => b.DefineTool("Big", new Vector(0, 0, 1e308), Rotation.Identity)),
    ];

    [Fact]
    public async Task Ur_AbsoluteValuesBeyondTheInt32Wire_AreRefusedAtIssueTime()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller);
        try
        {
            string[] refused =
            [
                .. new Action<Robot>[]
                {
                    b => b.MoveTo(1e308, 0, 0), b => b.Wait(int.MaxValue), b => b.SpeedTo(1e308), b => b.AccelerationTo(3e8), b => b.PrecisionTo(1e308),
                    b => b.WriteAnalog(1, 2148), b => b.AxesTo(0, 0, 1.3e7, 0, 0, 0), b => b.DefineTool("Big", new Vector(0, 0, 3e8), Rotation.Identity),
                }.Select(issue => Assert.Throws<ActionRefusedException>(() => issue(bot)).Message),
            ];

            // The target is refused by the general 1 km rule once applied, before the wire's own check.
            Assert.StartsWith("Cannot apply \"MoveTo(1E+308,0,0);\": the tool position would become", refused[0], StringComparison.Ordinal);
            Assert.Equal("Cannot apply \"WriteAnalog(1,2148);\": \"Set analog IO 1 to 2148\" cannot be streamed to a UR robot: UR analog outputs take a value from 0 to 1 (a fraction of the output's current or voltage range), not 2148.", refused[5]);
            Assert.EndsWith("which no robot reaches.", refused[6], StringComparison.Ordinal); // the general joint rule, also before the wire's
            // The general bounds on waits, settings and tools (what every robot language holds) come before the wire's own.
            Assert.EndsWith("the longest every robot language's timer holds.", refused[1], StringComparison.Ordinal);
            Assert.All([refused[2], refused[3], refused[4]], m => Assert.EndsWith("which no robot or printer uses and not every robot language can hold.", m, StringComparison.Ordinal));
            Assert.Contains("tool coordinates are refused beyond 1,000,000 mm (1 km)", refused[7], StringComparison.Ordinal);
            Assert.Equal(8, refused.Length);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    /// <summary>
    /// Values the state reaches through a relative action (or a setting) that the brand's encoding cannot carry: UR's 32-bit
    /// integers (0.001 mm), the 32-bit floats of RAPID's num and KRL's REAL. The general bounds (1 km for targets, 1,000,000 in its
    /// unit for a setting) now refuse them first, with the same words online and offline. Each is refused at issue time with the
    /// reason, nothing is sent, the state is unchanged, and the link then runs a normal move.
    /// </summary>
    public static TheoryData<string, string, string> BeyondTheWire() => new()
    {
        { "UR", "Move(-1e308, 0, 0)", "Cannot apply \"Move(-1E+308,0,0);\": the tool position would become [-1E+308, 100, 500] mm; targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches." },
        { "UR", "Speed(3e8)", "Cannot apply \"Speed(300000000);\": the speed would become 300000100 mm/s; settings are refused beyond 1,000,000 mm/s, which no robot or printer uses and not every robot language can hold." },
        { "UR", "Precision(3e8)", "Cannot apply \"Precision(300000000);\": the precision would become 300000000 mm; settings are refused beyond 1,000,000 mm, which no robot or printer uses and not every robot language can hold." },
        { "UR", "Acceleration(3e8)", "Cannot apply \"Acceleration(300000000);\": the acceleration would become 300000030 mm/s^2; settings are refused beyond 1,000,000 mm/s^2, which no robot or printer uses and not every robot language can hold." },
        { "ABB", "Move(-1e308, 0, 0)", "Cannot apply \"Move(-1E+308,0,0);\": the tool position would become [-1E+308, 100, 500] mm; targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches." },
        { "ABB", "SpeedTo(1e308)", "Cannot apply \"SpeedTo(1E+308);\": the speed would become 1E+308 mm/s; settings are refused beyond 1,000,000 mm/s, which no robot or printer uses and not every robot language can hold." },
        { "ABB", "Speed(1e308)", "Cannot apply \"Speed(1E+308);\": the speed would become 1E+308 mm/s; settings are refused beyond 1,000,000 mm/s, which no robot or printer uses and not every robot language can hold." },
        { "ABB", "WriteAnalog(\"AO_1\", 1e308)", "Cannot apply \"WriteAnalog(\"AO_1\",1E+308);\": the analog output AO_1 would be set to 1E+308; analog values are refused beyond ±1,000,000, which no output takes and not every robot language can hold." },
        { "KUKA", "Move(-1e308, 0, 0)", "Cannot apply \"Move(-1E+308,0,0);\": the tool position would become [-1E+308, 100, 500] mm; targets are refused beyond 1,000,000 mm (1 km) from the origin along X, Y or Z, which no robot or printer reaches." },
        { "KUKA", "SpeedTo(1e308)", "Cannot apply \"SpeedTo(1E+308);\": the speed would become 1E+308 mm/s; settings are refused beyond 1,000,000 mm/s, which no robot or printer uses and not every robot language can hold." },
        { "KUKA", "Precision(1e308)", "Cannot apply \"Precision(1E+308);\": the precision would become 1E+308 mm; settings are refused beyond 1,000,000 mm, which no robot or printer uses and not every robot language can hold." },
    };

    private static readonly Dictionary<string, Action<Robot>> Overflows = new()
    {
        ["Move(-1e308, 0, 0)"] = b => b.Move(-1e308, 0, 0),
        ["Speed(3e8)"] = b => b.Speed(3e8),
        ["Precision(3e8)"] = b => b.Precision(3e8),
        ["Acceleration(3e8)"] = b => b.Acceleration(3e8),
        ["SpeedTo(1e308)"] = b => b.SpeedTo(1e308),
        ["Speed(1e308)"] = b => b.Speed(1e308),
        ["Precision(1e308)"] = b => b.Precision(1e308),
        ["WriteAnalog(\"AO_1\", 1e308)"] = b => b.WriteAnalog("AO_1", 1e308),
    };

    [Theory]
    [MemberData(nameof(BeyondTheWire))]
    public async Task ValueTheWireCannotCarry_IsRefusedAtIssueTime_AndTheLinkRunsTheNextMove(string brand, string what, string message)
    {
        await using Controller controller = await Controller.StartAsync(brand);
        Robot bot = await controller.ConnectAsync(brand);
        try
        {
            bot.SpeedTo(100);
            bot.PrecisionTo(0);
            bot.TransformTo(new Vector(300, 100, 500), Rotation.FlippedAroundY);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));
            RobotState before = bot.GetCurrentState();
            int received = controller.RequestsReceived;

            var refused = Assert.Throws<ActionRefusedException>(() => Overflows[what](bot));

            Assert.Equal(message, refused.Message);
            Support.StateAssert.Same(before, bot.GetCurrentState());
            Assert.Empty(bot.GetPendingActions());
            bot.MoveTo(300, -100, 500);
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit), "the move after the refusal was not executed");
            Assert.True(bot.IsConnected);
            Assert.True(Vector.Distance(new Vector(300, -100, 500), controller.Position) < 0.01, $"the robot is at {controller.Position}");
            Assert.Equal(received + 1, controller.RequestsReceived);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    /// <summary>A multi-statement Do checks every statement, the wire's limits included, before it issues any (ids not given yet).</summary>
    [Theory]
    [MemberData(nameof(Brands))]
    public async Task Do_AStatementTheWireCannotCarry_IssuesNone(string brand)
    {
        await using Controller controller = await Controller.StartAsync(brand);
        Robot bot = await controller.ConnectAsync(brand);
        try
        {
            int received = controller.RequestsReceived;
            var refused = Assert.Throws<ActionRefusedException>(() => bot.Do("SpeedTo(100);\nMoveTo(300,100,500);\nSpeed(1e308);"));

            Assert.Equal("Speed(1E+308);", refused.Action.ToInstruction());
            Assert.Equal(-1, refused.Action.Id);
            Assert.Empty(bot.GetPendingActions());
            bot.Do("SpeedTo(100);\nTransformTo(300,100,500, -1,0,0, 0,1,0);");
            Assert.True(bot.WaitForCompletion(OnlineTestSupport.Limit));
            Assert.Equal(received + 2, controller.RequestsReceived);
            Assert.True(Vector.Distance(new Vector(300, 100, 500), controller.Position) < 0.01, $"the robot is at {controller.Position}");
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    public static TheoryData<string> Brands() => new("ABB", "UR", "KUKA");

    [Theory]
    [MemberData(nameof(Brands))]
    public async Task Sample_EachEdgeRefusedOrExecuted_ThenANormalMoveEndsWhereItShould(string brand)
    {
        await using Controller controller = await Controller.StartAsync(brand);
        Robot bot = await controller.ConnectAsync(brand);
        var outcomes = new List<string>();
        try
        {
            int step = 0;
            foreach ((string what, Action<Robot> issue) in Sample)
            {
                string outcome;
                try
                {
                    issue(bot);
                    outcome = "issued";
                }
                catch (Exception e) when (e is ArgumentException or ActionRefusedException)
                {
                    outcome = "refused";
                    Assert.False(string.IsNullOrWhiteSpace(e.Message));
                }
                // Whatever became of it, the link serves a normal move, which ends where it should.
                var target = new Vector(300, step++ % 2 == 0 ? 100 : -100, 500);
                bot.SpeedTo(100);
                bot.PrecisionTo(0);
                bot.TransformTo(target, Rotation.FlippedAroundY);
                bool done;
                try
                {
                    done = bot.WaitForCompletion(OnlineTestSupport.Limit);
                }
                catch (MachinaException e)
                {
                    throw new InvalidOperationException($"after {what} ({outcome}), the link failed: {e.Message}; controller errors: {string.Join(" | ", controller.Errors)}", e);
                }
                Assert.True(done, $"after {what} ({outcome}), the move was not acknowledged; errors: {string.Join(" | ", controller.Errors)}");
                Assert.True(bot.IsConnected, $"after {what} ({outcome}), the link closed");
                Vector reached = controller.Position;
                Assert.True(Vector.Distance(target, reached) < 0.01, $"after {what} ({outcome}), the robot is at {reached}, not {target}");
                outcomes.Add($"{what}: {outcome}");
            }
        }
        finally
        {
            await bot.DisconnectAsync();
        }
        Assert.Equal(Sample.Length, outcomes.Count);
    }

    /// <summary>One of the three virtual controllers, instant execution, loopback, OS-chosen ports.</summary>
    private sealed class Controller : IAsyncDisposable
    {
        private readonly IAsyncDisposable _inner;
        private readonly Func<Vector> _position;
        private readonly Func<IReadOnlyList<string>> _errors;

        private readonly Func<int> _received;

        private Controller(IAsyncDisposable inner, int port, Func<Vector> position, Func<IReadOnlyList<string>> errors, Func<int> received)
        {
            (_inner, Port, _position, _errors, _received) = (inner, port, position, errors, received);
        }

        internal int RequestsReceived => _received();

        /// <summary>A robot of <paramref name="brand"/> connected online to this controller (bounded waits).</summary>
        internal async Task<Robot> ConnectAsync(string brand)
        {
            Robot bot = Robot.Create("Edge", brand);
            bot.ControlMode("online");
            bot.ConnectTimeout = OnlineTestSupport.Limit;
            await bot.ConnectAsync("127.0.0.1", Port).WaitAsync(OnlineTestSupport.Limit);
            return bot;
        }

        internal int Port { get; }

        internal Vector Position => _position();

        internal IReadOnlyList<string> Errors => _errors();

        internal static async Task<Controller> StartAsync(string brand)
        {
            switch (brand)
            {
                case "ABB":
                    VirtualAbbController abb = await OnlineTestSupport.StartControllerAsync();
                    return new Controller(abb, abb.Port, () => abb.State.Position, () => abb.Errors, () => abb.RequestsReceived);
                case "UR":
                    VirtualUrController ur = await UrOnlineTestSupport.StartUrAsync();
                    return new Controller(ur, ur.Port, () => ur.State.Position, () => ur.Errors, () => ur.RequestsReceived);
                default:
                    VirtualKukaController kuka = await KukaTestSupport.StartKukaAsync();
                    return new Controller(kuka, kuka.Port, () => kuka.State.Position, () => kuka.Errors, () => kuka.RequestsReceived);
            }
        }

        public ValueTask DisposeAsync() => _inner.DisposeAsync();
    }
}

namespace Machina.Benchmarks;

/// <summary>
/// The host alone: the plain program of <see cref="PlainProgramScenario"/> (<c>Robot.Create</c>, online, <c>ConnectAsync</c>,
/// <c>SpeedTo(200)</c>, <c>Move(±1, 0, 0)</c> per action, <c>WaitForCompletionAsync</c>, default window) against a device that
/// acknowledges every frame as it is sent, in this process (<see cref="InstantDevice"/>): no socket, no twin interpreter. The
/// brand's codec encodes every frame as it would for its controller; the row's CPU time over the size is the host's processor
/// time per action (issue, encode, the session's ledger, release, acknowledgement, execution), which the twins hide in every
/// whole-process row.
/// </summary>
internal sealed class HostOnlyScenario(RobotType brand) : Scenario
{
    private Robot? _bot;

    public override string Name => "host-" + brand.ToString().ToLowerInvariant();

    public override string Title => $"Host only: the plain program with the {brand} codec against an instant in-process device (no socket, no twin)";

    public override int TargetSize => 100_000;

    public override IReadOnlyList<int> ScalingSizes => [];

    public override Target Target => Catalog.HostOnlyTarget;

    public override bool MultiThreaded => true;

    public override Func<object?> Prepare(int size) => () =>
    {
        _bot?.Dispose();
        var bot = Robot.Create("Host", brand.ToString());
        _bot = bot;
        var device = new InstantDevice();
        bot.DriverFactory = () => device;
        bot.ControlMode("online");
        bot.ConnectAsync("127.0.0.1", 1).GetAwaiter().GetResult();
        PlainProgramScenario.Stream(bot, size);
        // Every move went through the brand's codec: at least a byte each, acknowledged.
        return device.Bytes >= size && device.Acknowledged >= size
            ? null
            : throw new InvalidOperationException($"{Name}: {device.Bytes} bytes and {device.Acknowledged} acknowledgements for {size} moves.");
    };

    public override void Cleanup()
    {
        _bot?.Dispose();
        _bot = null;
    }

    /// <summary>
    /// A device that is only an acknowledgement: it takes each frame the session releases (its bytes are counted, not written) and
    /// acknowledges it at once on the sending thread (the acknowledgement is posted to the session's loop like any driver's report).
    /// </summary>
    private sealed class InstantDevice : IDeviceDriver
    {
        private IDeviceListener? _listener;

        /// <summary>The bytes of every frame sent, as a check that the codec encoded them.</summary>
        public long Bytes { get; private set; }

        /// <summary>How many frames it acknowledged.</summary>
        public int Acknowledged { get; private set; }

        public string RemoteAddress => "instant";

        public Task<DeviceHandshake> ConnectAsync(string host, int port, IDeviceListener listener, TimeSpan timeout, CancellationToken cancellationToken)
        {
            _listener = listener;
            return Task.FromResult(new DeviceHandshake("9.9.9", new Vector(400, 0, 500), Rotation.FlippedAroundY, new Joints(0, 0, 0, 0, 90, 0), null));
        }

        public bool Send(RobotAction action, ActionFrame frame)
        {
            Bytes += frame.Bytes.Length;
            if (frame.Acknowledged)
            {
                Acknowledged++;
                _listener!.OnAcknowledged(action.Id);
            }
            return true;
        }

        public int WireId(int actionId) => actionId;

        public void Adopt(int actionId)
        {
        }

        public ValueTask DisposeAsync() => ValueTask.CompletedTask;
    }
}

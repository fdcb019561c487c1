namespace Machina.Simulation;

/// <summary>
/// The virtual controller of each brand that has one, keyed by the brands of Machina's brand list (docs/architecture.md, "Brands").
/// The command line (<c>machina sim</c>, <c>machina run --sim</c>), the bridge and the samples start their controllers here, so that a
/// new brand's virtual controller is one line in this file. The library does not reference this assembly, which is why the list lives here.
/// </summary>
public static class VirtualControllerRegistry
{
    private sealed record Entry(BrandDefinition Brand, Func<VirtualControllerOptions> Defaults, Func<VirtualControllerOptions, RunningVirtualController> Create,
        bool ListensWhereAsked = false)
    {
        /// <summary>The ports of the vendor's own simulator, where its clients look (name as in the port names, port), or null.</summary>
        public (string Name, int Port)[]? VendorPorts { get; init; }

        /// <summary>The settings that make the twin stand in for the vendor's simulator at <see cref="VendorPorts"/>, or null.</summary>
        public Func<VirtualControllerOptions, VirtualControllerOptions>? AsVendorSimulator { get; init; }

        /// <summary>What a person starting the stand-in must know first (UR: the arm is powered off), or null.</summary>
        public string? VendorSimulatorNote { get; init; }

        /// <summary>The settings with the controller's mass memory in a folder, for a brand whose controller has one; or null.</summary>
        public Func<VirtualControllerOptions, string, VirtualControllerOptions>? WithHome { get; init; }

        /// <summary>Starts the controller's web services (given the brand's controller object), or null when it serves none.</summary>
        public Func<IAsyncDisposable, Twin.TwinWebServices?>? WebServices { get; init; }
    }

    private static readonly Entry[] Entries =
    [
        new(AbbBrand.Definition, () => new VirtualAbbControllerOptions(), o =>
        {
            var c = new VirtualAbbController((VirtualAbbControllerOptions)o);
            return new Running<VirtualAbbState>(AbbBrand.Definition.Type, c, c.StartAsync, ["driver", "monitor"], () => [c.Port, c.MonitorPort], "requests", "malformed", () => c.Twin?.Io);
        }, ListensWhereAsked: true)
        {
            WithHome = (o, home) => (VirtualAbbControllerOptions)o with { HomeDirectory = home },
            WebServices = c => c is VirtualAbbController { Twin: { } twin } ? Rws.RwsWebServices.Serve(twin) : null,
        },
        new(UrBrand.Definition, () => new VirtualUrControllerOptions(), o =>
        {
            var options = (VirtualUrControllerOptions)o;
            var c = new VirtualUrController(options);
            (string Name, bool Served, Func<int> Port)[] ports =
            [
                ("script", true, () => c.Port), ("RTDE", true, () => c.RtdePort), ("dashboard", true, () => c.DashboardPort),
                ("primary", options.PrimaryPort is not null, () => c.PrimaryPort), ("secondary", options.SecondaryPort is not null, () => c.SecondaryPort),
                ("real-time", options.RealtimePort is not null, () => c.RealtimePort),
            ];
            var served = ports.Where(p => p.Served).ToArray();
            return new Running<VirtualUrState>(UrBrand.Definition.Type, c, c.StartAsync, [.. served.Select(p => p.Name)], () => [.. served.Select(p => p.Port())], "instructions", "refused", () => c.Twin.Io);
        })
        {
            // URSim's ports: the client interfaces (the first takes scripts), RTDE and the dashboard.
            VendorPorts = [("primary", 30001), ("secondary", 30002), ("real-time", 30003), ("RTDE", 30004), ("dashboard", 29999)],
            // URSim serves its client interfaces and starts powered off (a program runs after "power on" and "brake release").
            AsVendorSimulator = o => (VirtualUrControllerOptions)o with { PrimaryPort = 0, SecondaryPort = 0, RealtimePort = 0, StartsPoweredOff = true },
            VendorSimulatorNote = "The arm is powered off, as on URSim: send \"power on\" and \"brake release\" to the dashboard (29999) before a program runs.",
        },
        new(KukaBrand.Definition, () => new VirtualKukaControllerOptions(), o =>
        {
            var c = new VirtualKukaController((VirtualKukaControllerOptions)o);
            return new Running<VirtualKukaState>(KukaBrand.Definition.Type, c, c.StartAsync, ["driver", "monitor"], () => [c.Port, c.MonitorPort], "requests", "refused", () => c.Twin?.Io);
        }, ListensWhereAsked: true),
    ];

    /// <summary>The brands that have a virtual controller, in the order of Machina's brand list.</summary>
    public static IReadOnlyList<RobotType> Brands => [.. Entries.Select(e => e.Brand.Type)];

    /// <summary>True when <paramref name="brand"/> has a virtual controller.</summary>
    public static bool Has(RobotType brand) => Array.Exists(Entries, e => e.Brand.Type == brand);

    /// <summary>The brand with a virtual controller named <paramref name="name"/> (e.g. "abb", "UR"; any letter case), or null.</summary>
    public static RobotType? Find(string name) => Array.Find(Entries, e => e.Brand.IsNamed(name))?.Brand.Type;

    /// <summary>
    /// True when the brand's controller listens at its options' <see cref="VirtualControllerOptions.ListenAddress"/> and
    /// <see cref="VirtualControllerOptions.ListenPort"/> and tells <see cref="VirtualControllerOptions.ConnectionSeen"/> (its ports
    /// are the driver's and the next); false: it listens on 127.0.0.1 at ports the system chooses.
    /// </summary>
    internal static bool ListensWhereAsked(RobotType brand) => EntryFor(brand).ListensWhereAsked;

    /// <summary>
    /// Where the vendor's own simulator of <paramref name="brand"/> listens, which its clients expect (UR: URSim's 30001-30004 and
    /// 29999; the first takes scripts), or null when the twin has no such layout.
    /// </summary>
    internal static IReadOnlyList<(string Name, int Port)>? VendorPorts(RobotType brand) => EntryFor(brand).VendorPorts;

    /// <summary><paramref name="options"/> made to stand in for the vendor's simulator (see <see cref="VendorPorts"/>); unchanged for a brand without one.</summary>
    internal static VirtualControllerOptions AsVendorSimulator(RobotType brand, VirtualControllerOptions options) =>
        EntryFor(brand).AsVendorSimulator is { } change ? change(options) : options;

    /// <summary>What a person starting the stand-in for the vendor's simulator must know first, or null.</summary>
    internal static string? VendorSimulatorNote(RobotType brand) => EntryFor(brand).VendorSimulatorNote;

    /// <summary>True when the brand's controller has a mass memory that <see cref="WithHome"/> puts in a folder (ABB: RAPID's HOME:).</summary>
    internal static bool HasHome(RobotType brand) => EntryFor(brand).WithHome is not null;

    /// <summary><paramref name="options"/> with the controller's mass memory in <paramref name="folder"/>.</summary>
    /// <exception cref="ArgumentException">The brand's controller has no mass memory (see <see cref="HasHome"/>).</exception>
    internal static VirtualControllerOptions WithHome(RobotType brand, VirtualControllerOptions options, string folder) =>
        EntryFor(brand).WithHome is { } change ? change(options, folder)
            : throw new ArgumentException($"A virtual {EntryFor(brand).Brand.DisplayName} controller has no mass memory.", nameof(brand));

    /// <summary>The brands whose controller has a mass memory (see <see cref="HasHome"/>).</summary>
    internal static IReadOnlyList<BrandDefinition> WithMassMemory => [.. Entries.Where(e => e.WithHome is not null).Select(e => e.Brand)];

    /// <summary>
    /// Starts the web services of <paramref name="controller"/>'s brand on 127.0.0.1 at a free port (ABB: Robot Web Services in front of
    /// its RAPID tasks), or returns null when the brand's controller serves none, or this one runs no program they act on.
    /// </summary>
    internal static Twin.TwinWebServices? StartWebServices(RunningVirtualController controller) =>
        EntryFor(controller.Brand).WebServices?.Invoke(controller.Controller);

    /// <summary>The port Machina's driver listens on on a real controller of <paramref name="brand"/> (UR: the robot's script port), for a default.</summary>
    public static int DriverPort(RobotType brand) => EntryFor(brand).Brand.DefaultPort;

    /// <summary>The default settings of a brand's virtual controller (its own options type, e.g. <see cref="VirtualAbbControllerOptions"/>), to change with <c>with</c>.</summary>
    /// <exception cref="ArgumentException">The brand has no virtual controller.</exception>
    public static VirtualControllerOptions DefaultOptions(RobotType brand) => EntryFor(brand).Defaults();

    /// <summary>
    /// Starts a virtual controller of <paramref name="brand"/> on 127.0.0.1 (OS-chosen ports), with <paramref name="options"/> (of the brand's
    /// options type, e.g. from <see cref="DefaultOptions"/>) or the brand's defaults.
    /// </summary>
    /// <exception cref="ArgumentException">The brand has no virtual controller, or the options are of another brand's type.</exception>
    public static async Task<RunningVirtualController> StartAsync(RobotType brand, VirtualControllerOptions? options = null, CancellationToken cancellationToken = default)
    {
        Entry entry = EntryFor(brand);
        VirtualControllerOptions settings = options ?? entry.Defaults();
        if (settings.GetType() != entry.Defaults().GetType())
        {
            throw new ArgumentException($"A virtual {entry.Brand.DisplayName} controller takes {entry.Defaults().GetType().Name}, not {settings.GetType().Name}.", nameof(options));
        }
        RunningVirtualController controller = entry.Create(settings);
        try
        {
            await controller.StartAsync(cancellationToken).ConfigureAwait(false);
        }
        catch
        {
            await controller.DisposeAsync().ConfigureAwait(false);
            throw;
        }
        return controller;
    }

    private static Entry EntryFor(RobotType brand) => Array.Find(Entries, e => e.Brand.Type == brand)
        ?? throw new ArgumentException(
            $"{brand} devices have no virtual controller; {string.Join(", ", Entries.Select(e => e.Brand.DisplayName))} have one.", nameof(brand));

    /// <summary>A started controller of one state type, seen through <see cref="RunningVirtualController"/>.</summary>
    private sealed class Running<TState>(RobotType brand, VirtualController<TState> c, Func<CancellationToken, Task> start, string[] portNames,
        Func<int[]> ports, string requestNoun, string errorWord, Func<Twin.TwinIo?> io) : RunningVirtualController(brand, c, portNames)
        where TState : VirtualRobotState
    {
        public override IReadOnlyList<int> Ports => ports();
        public override RobotModel? Model => c.Model;
        public override int RequestsReceived => c.RequestsReceived;
        public override IReadOnlyList<string> ReceivedRequests => c.ReceivedRequests;
        public override int RequestsExecuted => c.RequestsExecuted;
        public override IReadOnlyList<int> ExecutedIds => c.ExecutedIds;
        public override IReadOnlyList<string> PendantMessages => c.PendantMessages;
        public override IReadOnlyList<string> Errors => c.Errors;
        public override VirtualRobotState State => c.State;
        public override long ReceivedRequestsSince(long seen, ICollection<string> into) => c.ReceivedRequestsSince(seen, into);
        public override long ExecutedIdsSince(long seen, ICollection<int> into) => c.ExecutedIdsSince(seen, into);
        public override long PendantMessagesSince(long seen, ICollection<string> into) => c.PendantMessagesSince(seen, into);
        public override long ErrorsSince(long seen, ICollection<string> into) => c.ErrorsSince(seen, into);
        internal override (object? Signals, long Writes) OutputsMark => io() is { } signals ? (signals, signals.Writes) : (null, 0);

        internal override Twin.TwinChangeSignal Changes
        {
            get
            {
                if (io() is { } signals)
                {
                    signals.Changes = c.Changes; // the twin's signals tell the controller's readers too (the twin is made at start)
                }
                return c.Changes;
            }
        }

        public override string Summary() => $"{c.RequestsReceived} {requestNoun} received, {c.RequestsExecuted} executed, {c.Errors.Count} {errorWord}";
        private protected override Task StartCoreAsync(CancellationToken cancellationToken) => start(cancellationToken);
    }
}

/// <summary>
/// A virtual controller started from <see cref="VirtualControllerRegistry"/>, whatever its brand: where it listens and what it did,
/// until disposed. <see cref="Controller"/> is the brand's own controller (e.g. a <see cref="VirtualAbbController"/>) for more.
/// </summary>
public abstract class RunningVirtualController : IAsyncDisposable
{
    private protected RunningVirtualController(RobotType brand, IAsyncDisposable controller, string[] portNames)
    {
        Brand = brand;
        Controller = controller;
        PortNames = portNames;
    }

    /// <summary>The brand whose controller it imitates.</summary>
    public RobotType Brand { get; }

    /// <summary>The brand's own controller object (a <see cref="VirtualAbbController"/>, <see cref="VirtualUrController"/> or <see cref="VirtualKukaController"/>).</summary>
    public IAsyncDisposable Controller { get; }

    /// <summary>What each port is for (ABB and KUKA: "driver", "monitor"; UR: "script", "RTDE", "dashboard", then "primary", "secondary" and "real-time" when served), in the order of <see cref="Ports"/>.</summary>
    public IReadOnlyList<string> PortNames { get; }

    /// <summary>The ports it listens on, on 127.0.0.1; the first is the one a Machina host connects to.</summary>
    public abstract IReadOnlyList<int> Ports { get; }

    /// <summary>The port a Machina host connects to.</summary>
    public int Port => Ports[0];

    /// <summary>The arm it moves like, or null.</summary>
    public abstract RobotModel? Model { get; }

    /// <summary>How many requests (instructions) it has read.</summary>
    public abstract int RequestsReceived { get; }

    /// <summary>The last requests it read, oldest first.</summary>
    public abstract IReadOnlyList<string> ReceivedRequests { get; }

    /// <summary>How many requests it has executed.</summary>
    public abstract int RequestsExecuted { get; }

    /// <summary>The ids of the last actions it executed, oldest first.</summary>
    public abstract IReadOnlyList<int> ExecutedIds { get; }

    /// <summary>What its pendant shows, oldest first.</summary>
    public abstract IReadOnlyList<string> PendantMessages { get; }

    /// <summary>What it refused or could not read (e.g. a target its arm cannot reach), oldest first.</summary>
    public abstract IReadOnlyList<string> Errors { get; }

    /// <summary>Its robot as it is now (pose, joints, tool, outputs).</summary>
    public abstract VirtualRobotState State { get; }

    /// <summary>
    /// Adds to <paramref name="into"/> the requests it read after the first <paramref name="seen"/> (those still kept, oldest
    /// first) and returns how many it ever read: the <paramref name="seen"/> of the next read. Nothing is copied when nothing is new.
    /// </summary>
    public abstract long ReceivedRequestsSince(long seen, ICollection<string> into);

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="ExecutedIds"/>.</summary>
    public abstract long ExecutedIdsSince(long seen, ICollection<int> into);

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="PendantMessages"/>.</summary>
    public abstract long PendantMessagesSince(long seen, ICollection<string> into);

    /// <summary>As <see cref="ReceivedRequestsSince"/>, for <see cref="Errors"/>.</summary>
    public abstract long ErrorsSince(long seen, ICollection<string> into);

    /// <summary>
    /// Changes whenever its outputs may have changed (the object that holds its twin's signals, and how many times they were
    /// written): a reader that shows the outputs reads <see cref="State"/> again only then.
    /// </summary>
    internal abstract (object? Signals, long Writes) OutputsMark { get; }

    /// <summary>
    /// Set whenever what its inspection members show changes (its twin's signals too): one reader (<c>machina sim</c>'s activity)
    /// sleeps on it between two looks, so an idle controller wakes no thread. Read it again after each look: that attaches the
    /// twin's signals, should the twin have been made since.
    /// </summary>
    internal abstract Twin.TwinChangeSignal Changes { get; }

    /// <summary>One line of what it did, e.g. "12 requests received, 12 executed, 0 malformed".</summary>
    public abstract string Summary();

    /// <summary>Stops it and closes its connections.</summary>
    public ValueTask DisposeAsync() => Controller.DisposeAsync();

    internal Task StartAsync(CancellationToken cancellationToken) => StartCoreAsync(cancellationToken);

    private protected abstract Task StartCoreAsync(CancellationToken cancellationToken);
}

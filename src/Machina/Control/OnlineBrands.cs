namespace Machina;

/// <summary>The registry of the brands that can be controlled online: one <see cref="IOnlineBrand"/> each.</summary>
internal static class OnlineBrands
{
    private static readonly IOnlineBrand[] Supported = [new AbbOnline(), new UrOnline(), new KukaOnline()];

    /// <summary>The online support of a brand, or null when it has none.</summary>
    internal static IOnlineBrand? TryFor(RobotType brand) => Array.Find(Supported, b => b.Brand == brand);

    /// <summary>The online support of a brand, or an exception that says why the brand cannot go online.</summary>
    internal static IOnlineBrand For(RobotType brand) =>
        TryFor(brand) ?? throw (brand is RobotType.UR or RobotType.KUKA
            ? new NotSupportedException($"Online control of {brand} robots is not available in this version yet; only {Names()} robots can go online.")
            : new ArgumentException($"{brand} robots cannot be controlled online; only ABB, UR and KUKA robots can.", nameof(brand)));

    /// <summary>The driver files of a brand (see <see cref="IOnlineBrand.DriverModules"/>), or an exception for a brand without any.</summary>
    internal static IReadOnlyDictionary<string, string> DriverModules(RobotType brand, IReadOnlyDictionary<string, string> parameters) =>
        (TryFor(brand) ?? throw new NotSupportedException($"Machina has no driver modules for {brand} robots; {Names()} robots have them."))
            .DriverModules(parameters);

    private static string Names() => string.Join(", ", Supported.Select(b => b.Brand));
}

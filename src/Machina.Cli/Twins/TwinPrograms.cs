namespace Machina.Cli.Twins;

/// <summary>
/// The twin controllers the command line runs programs on (<c>machina verify</c>, <c>machina sim BRAND --load</c>), one per brand that
/// has one: a new brand's twin is a class beside these and one line here.
/// </summary>
internal static class TwinPrograms
{
    /// <summary>Every twin, in the order help and error texts list them.</summary>
    internal static IReadOnlyList<ITwinProgram> All { get; } = [new UrScriptTwinProgram(), new RapidTwinProgram(), new KrlTwinProgram()];

    /// <summary>The brands with a twin, in the order of <see cref="All"/>.</summary>
    internal static IReadOnlyList<RobotType> Brands { get; } = [.. All.Select(t => t.Brand.Type)];

    /// <summary>The twin of <paramref name="brand"/> (one of <see cref="Brands"/>).</summary>
    internal static ITwinProgram For(RobotType brand) => All.First(t => t.Brand.Type == brand);

    /// <summary>The twins that load programs from <c>machina sim BRAND --load</c>, in the order of <see cref="All"/>.</summary>
    internal static IEnumerable<ITwinProgram> Loading => All.Where(t => t.RunLoaded is not null);
}

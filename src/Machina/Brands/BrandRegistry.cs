namespace Machina;

/// <summary>
/// THE list of brands (docs/architecture.md, "Brands"): one <see cref="BrandDefinition"/> per brand, declared in the brand's folder.
/// Adding a brand is a folder with its definition and one line here (two for an arm: <see cref="Catalogue"/>); nothing else in
/// Machina names a brand but the few exceptions <c>tests/Machina.Tests/Brands/Registry/BrandCodeTests.cs</c> lists with their reasons.
/// </summary>
/// <remarks>
/// Each brand's definition is made when it is first asked for: <see cref="For"/> (a robot's compiler, its online brand) makes only
/// the brand asked, and <see cref="All"/> makes them all when it is first read. A script that compiles for one brand then builds
/// one definition, not seven (every definition, its online support and timing types were some seventy methods the JIT compiled
/// in a fresh process's first <c>Compile()</c>, docs/performance.md, session 29).
/// </remarks>
internal static class BrandRegistry
{
    /// <summary>Every brand, in the order help texts list them (the arms, the printers, then the listings): its type and its definition, made at the first call.</summary>
    private static readonly (RobotType Type, Func<BrandDefinition> Definition)[] Entries =
    [
        (RobotType.ABB, static () => AbbBrand.Definition),
        (RobotType.UR, static () => UrBrand.Definition),
        (RobotType.KUKA, static () => KukaBrand.Definition),
        (RobotType.ZMORPH, static () => ZMorphBrand.Definition),
        (RobotType.MARLIN, static () => MarlinBrand.Definition),
        (RobotType.HUMAN, static () => HumanBrand.Definition),
        (RobotType.MACHINA, static () => MachinaTextBrand.Definition),
    ];

    /// <summary>Every brand, in the order help texts list them: the arms, the printers, then the listings.</summary>
    internal static IReadOnlyList<BrandDefinition> All => Made.All;

    /// <summary>The order of the brands' arms in <see cref="RobotModels.All"/> (and so in <c>machina models</c>): UR's first, as it always was.</summary>
    internal static IReadOnlyList<BrandDefinition> Catalogue => Made.Catalogue;

    /// <summary>The brands that can be controlled online, in the order of <see cref="All"/>.</summary>
    internal static IReadOnlyList<BrandDefinition> Online => Made.Online;

    /// <summary>The brand a robot has when none is given (<c>Robot.Create()</c>): the human-readable listing.</summary>
    internal static BrandDefinition Default => HumanBrand.Definition;

    /// <summary>The brand a connection defaults to when none is given (the bridge, the samples): the first online brand.</summary>
    internal static BrandDefinition DefaultOnline => Online[0];

    /// <summary>The definition of <paramref name="brand"/> (made now if it was not yet; no other brand's is).</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not a brand (a number cast to <see cref="RobotType"/>).</exception>
    internal static BrandDefinition For(RobotType brand) =>
        TryFor(brand) ?? throw new ArgumentOutOfRangeException(nameof(brand), brand, "Unknown robot brand.");

    /// <summary>The definition of <paramref name="brand"/>, or null when the value is not a brand; no other brand's definition is made.</summary>
    internal static BrandDefinition? TryFor(RobotType brand)
    {
        foreach ((RobotType type, Func<BrandDefinition> definition) in Entries)
        {
            if (type == brand)
            {
                return definition();
            }
        }
        return null;
    }

    /// <summary>The brand named <paramref name="text"/> (its name or an alias, any letter case), or null.</summary>
    internal static BrandDefinition? Find(string text) => All.FirstOrDefault(b => b.IsNamed(text));

    /// <summary>The lists of every brand, made together when one of them is first read (the runtime runs a type's initialiser once, on any thread).</summary>
    private static class Made
    {
        internal static readonly IReadOnlyList<BrandDefinition> All = [.. Entries.Select(e => e.Definition())];

        internal static readonly IReadOnlyList<BrandDefinition> Catalogue = [UrBrand.Definition, AbbBrand.Definition, KukaBrand.Definition];

        internal static readonly IReadOnlyList<BrandDefinition> Online = [.. All.Where(b => b.Online is not null)];
    }
}

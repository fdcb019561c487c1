namespace Machina;

/// <summary>
/// THE list of brands (docs/architecture.md, "Brands"): one <see cref="BrandDefinition"/> per brand, declared in the brand's folder.
/// Adding a brand is a folder with its definition and one line here (two for an arm: <see cref="Catalogue"/>); nothing else in
/// Machina names a brand but the few exceptions <c>tests/Machina.Tests/Brands/Registry/BrandCodeTests.cs</c> lists with their reasons.
/// </summary>
internal static class BrandRegistry
{
    /// <summary>Every brand, in the order help texts list them: the arms, the printers, then the listings.</summary>
    internal static IReadOnlyList<BrandDefinition> All { get; } =
        [AbbBrand.Definition, UrBrand.Definition, KukaBrand.Definition, ZMorphBrand.Definition, MarlinBrand.Definition, HumanBrand.Definition, MachinaTextBrand.Definition];

    /// <summary>The order of the brands' arms in <see cref="RobotModels.All"/> (and so in <c>machina models</c>): UR's first, as it always was.</summary>
    internal static IReadOnlyList<BrandDefinition> Catalogue { get; } = [UrBrand.Definition, AbbBrand.Definition, KukaBrand.Definition];

    /// <summary>The brands that can be controlled online, in the order of <see cref="All"/>.</summary>
    internal static IReadOnlyList<BrandDefinition> Online { get; } = [.. All.Where(b => b.Online is not null)];

    /// <summary>The brand a robot has when none is given (<c>Robot.Create()</c>): the human-readable listing.</summary>
    internal static BrandDefinition Default => HumanBrand.Definition;

    /// <summary>The brand a connection defaults to when none is given (the bridge, the samples): the first online brand.</summary>
    internal static BrandDefinition DefaultOnline => Online[0];

    /// <summary>The definition of <paramref name="brand"/>.</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not a brand (a number cast to <see cref="RobotType"/>).</exception>
    internal static BrandDefinition For(RobotType brand) =>
        All.FirstOrDefault(b => b.Type == brand) ?? throw new ArgumentOutOfRangeException(nameof(brand), brand, "Unknown robot brand.");

    /// <summary>The brand named <paramref name="text"/> (its name or an alias, any letter case), or null.</summary>
    internal static BrandDefinition? Find(string text) => All.FirstOrDefault(b => b.IsNamed(text));
}

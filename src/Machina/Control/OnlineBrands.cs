namespace Machina;

/// <summary>The brands that can be controlled online: the <see cref="BrandDefinition.Online"/> of each brand in <see cref="BrandRegistry"/>.</summary>
internal static class OnlineBrands
{
    /// <summary>The online support of a brand, or null when it has none.</summary>
    internal static IOnlineBrand? TryFor(RobotType brand) => BrandRegistry.Online.FirstOrDefault(b => b.Type == brand)?.Online;

    /// <summary>The online support of a brand, or an exception that says why the brand cannot go online.</summary>
    internal static IOnlineBrand For(RobotType brand) =>
        TryFor(brand) ?? throw (BrandRegistry.All.Any(b => b.Type == brand && b.IsArm)
            ? new NotSupportedException($"Online control of {brand} robots is not available in this version yet; only {Names(", ")} robots can go online.")
            : new ArgumentException($"{brand} robots cannot be controlled online; only {Names(" and ")} robots can.", nameof(brand)));

    /// <summary>The driver files of a brand (see <see cref="IOnlineBrand.DriverModules"/>), or an exception for a brand without any.</summary>
    internal static IReadOnlyDictionary<string, string> DriverModules(RobotType brand, IReadOnlyDictionary<string, string> parameters) =>
        (TryFor(brand) ?? throw new NotSupportedException($"Machina has no driver modules for {brand} robots; {Names(", ")} robots have them."))
            .DriverModules(parameters);

    /// <summary>"ABB, UR, KUKA" (or "ABB, UR and KUKA" with <paramref name="last"/> = " and ").</summary>
    private static string Names(string last)
    {
        string[] names = [.. BrandRegistry.Online.Select(b => b.DisplayName)];
        return names.Length < 2 ? string.Join("", names) : string.Join(", ", names[..^1]) + last + names[^1];
    }
}

namespace Machina;

/// <summary>Machina's own instruction text, which can be read back with <c>Do</c>: compiled only (see <see cref="BrandRegistry"/>).</summary>
internal static class MachinaTextBrand
{
    /// <summary>Machina's instruction text.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.MACHINA, "machina", BrandKind.Listing, () => new MachinaCompiler());
}

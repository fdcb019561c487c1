namespace Machina;

/// <summary>A numbered, human-readable listing of the actions: compiled only, the brand of <c>Robot.Create()</c> (see <see cref="BrandRegistry"/>).</summary>
internal static class HumanBrand
{
    /// <summary>The human-readable listing.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.HUMAN, "human", BrandKind.Listing, () => new HumanCompiler());
}

namespace Machina;

/// <summary>Generic Marlin 3D printers: G-code in Marlin's flavour, compiled only (see <see cref="BrandRegistry"/>).</summary>
internal static class MarlinBrand
{
    /// <summary>The Marlin brand.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.MARLIN, "marlin", BrandKind.Printer, () => new GCodeCompiler(GCodeFlavor.Marlin));
}

namespace Machina;

/// <summary>ZMorph 3D printers: G-code in ZMorph's flavour, compiled only (see <see cref="BrandRegistry"/>).</summary>
internal static class ZMorphBrand
{
    /// <summary>The ZMorph brand.</summary>
    internal static BrandDefinition Definition { get; } = new(RobotType.ZMORPH, "zmorph", BrandKind.Printer, () => new GCodeCompiler(GCodeFlavor.ZMorph));
}

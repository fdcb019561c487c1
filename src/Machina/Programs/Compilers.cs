namespace Machina;

/// <summary>Finds the compiler for a device language, in the brand's definition (<see cref="BrandRegistry"/>).</summary>
internal static class Compilers
{
    /// <summary>A new compiler for <paramref name="brand"/> (only that brand's definition is made, <see cref="BrandRegistry.TryFor"/>).</summary>
    /// <exception cref="ArgumentOutOfRangeException">The value is not a brand.</exception>
    internal static Compiler For(RobotType brand) =>
        BrandRegistry.TryFor(brand)?.CreateCompiler()
        ?? throw new ArgumentOutOfRangeException(nameof(brand), brand, "Unknown robot language.");
}

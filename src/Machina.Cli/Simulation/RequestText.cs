namespace Machina.Cli.Simulation;

/// <summary>
/// A request as a virtual controller read it, with the name of its instruction in front: <c>MoveL  @2 1 350 50 500 …;</c> (ABB),
/// <c>MoveL  2 1 3000 1000 4000 …</c> (UR, values in the driver's integer units), <c>Linear  &lt;A ID="2" T="1" …/&gt;</c> (KUKA).
/// The names are those of Machina's protocols (docs/protocol-*.md); an unknown code is shown as it is.
/// </summary>
internal static class RequestText
{
    /// <summary>The request of a <paramref name="brand"/> controller with its instruction's name, or as it is when it has none.</summary>
    internal static string Describe(RobotType brand, string request) =>
        BrandRegistry.For(brand).InstructionName(request) is string name ? $"{name,-16}{request}" : request;
}

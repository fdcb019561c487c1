namespace Machina;

/// <summary>Finds the compiler for a device language.</summary>
internal static class Compilers
{
    /// <summary>The compiler for <paramref name="brand"/>.</summary>
    internal static Compiler For(RobotType brand) => brand switch
    {
        RobotType.HUMAN => new HumanCompiler(),
        RobotType.MACHINA => new MachinaCompiler(),
        RobotType.ABB => new RapidCompiler(),
        RobotType.UR => new UrScriptCompiler(),
        _ => throw new NotSupportedException($"Compiling to {brand} is not available yet."),
    };
}

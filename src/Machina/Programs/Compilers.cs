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
        RobotType.KUKA => new KrlCompiler(),
        RobotType.ZMORPH => new GCodeCompiler(GCodeFlavor.ZMorph),
        RobotType.MARLIN => new GCodeCompiler(GCodeFlavor.Marlin),
        _ => throw new ArgumentOutOfRangeException(nameof(brand), brand, "Unknown robot language."),
    };
}

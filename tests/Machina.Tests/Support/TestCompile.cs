namespace Machina.Tests.Support;

/// <summary>Compiles a few actions issued on a fresh robot, as the compiler tests do.</summary>
internal static class TestCompile
{
    /// <summary>No human-readable comments: only the native lines, which the tests compare.</summary>
    internal static readonly CompileOptions Plain = new() { HumanComments = false };

    /// <summary>Issues <paramref name="issue"/> on a new robot of <paramref name="brand"/> and compiles it (plain unless told).</summary>
    internal static RobotProgram Program(RobotType brand, Action<Robot> issue, CompileOptions? options = null, string name = "Demo")
    {
        var bot = Robot.Create(name, brand);
        issue(bot);
        return bot.Compile(brand, options ?? Plain);
    }
}

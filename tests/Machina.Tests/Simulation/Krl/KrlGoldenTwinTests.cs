using Machina.Simulation.Krl;
using Machina.Simulation.Twin;
using Machina.Tests.Support;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation.Krl;

/// <summary>Every KRL golden program loads on the KRL twin, runs its main routine and ends where the library's cursor says, step by step.</summary>
public class KrlGoldenTwinTests(ITestOutputHelper output)
{
    private static (string, string)[] Files(string program, string file, params string[] more) =>
    [
        (program + ".src", File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "Golden", "KUKA", file))),
        .. more.Select(m => (program + Path.GetExtension(m), File.ReadAllText(Path.Combine(AppContext.BaseDirectory, "Golden", "KUKA", m)))),
    ];

    [Theory]
    [InlineData("HelloRobot", "HelloRobot.src", null)]
    [InlineData("HelloRobot", "HelloRobot.nocomments.src", null)]
    [InlineData("HelloRobot", "HelloRobot.targets.src", "HelloRobot.targets.dat")]
    [InlineData("JointsToolsIO", "JointsToolsIO.src", null)]
    [InlineData("Print3D", "Print3D.src", null)]
    [InlineData("Rotations", "Rotations.src", null)]
    [InlineData("SquarePushPop", "SquarePushPop.src", null)]
    public void GoldenProgram_RunsOnTheTwin_AndMatchesTheCursorStepByStep(string name, string file, string? data)
    {
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue(name, RobotType.KUKA).GetProgramActions();

        TwinVerification<KrlProgramState> result = KrlVerifier.Verify(data is null ? Files(name, file) : Files(name, file, data), actions);

        output.WriteLine(result.ToText());
        Assert.True(result.Passed, result.ToText());
        Assert.Equal(KrlProgramState.Finished, result.State);
        Assert.Equal(actions.Count(a => a is ActionTranslation or ActionRotation or ActionTransformation or ActionAxes
            || a is ActionIODigital or ActionIOAnalog), result.Steps.Count);
    }
}

using Machina.Tests.Support;

namespace Machina.Tests.Brands.Abb;

public class RapidGoldenTests
{
    public static TheoryData<string> Programs => [.. ReferencePrograms.All.Keys];

    [Theory]
    [MemberData(nameof(Programs))]
    public void Compile_ReferenceProgram_MatchesGoldenFile(string name)
    {
        GoldenFiles.Check(name, RobotType.ABB);
    }

    [Theory]
    [MemberData(nameof(Programs))]
    public void Compile_ReferenceProgramWithDeclaredTargets_MatchesGoldenFile(string name)
    {
        GoldenFiles.Check(name, RobotType.ABB, "declared", new CompileOptions { InlineTargets = false });
    }

    [Fact]
    public void Compile_HelloRobotWithoutHumanComments_MatchesGoldenFile()
    {
        GoldenFiles.Check("HelloRobot", RobotType.ABB, "plain", new CompileOptions { HumanComments = false });
    }

    [Fact]
    public void Compile_HelloRobotDeclaredWithoutComments_MatchesGoldenFile()
    {
        GoldenFiles.Check("HelloRobot", RobotType.ABB, "declared-plain", new CompileOptions { InlineTargets = false, HumanComments = false });
    }
}

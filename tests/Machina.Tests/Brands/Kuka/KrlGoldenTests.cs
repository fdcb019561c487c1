using Machina.Tests.Support;

namespace Machina.Tests.Brands.Kuka;

public class KrlGoldenTests
{
    /// <summary>The names of the reference programs, for theories.</summary>
    public static TheoryData<string> ReferenceProgramNames => new(ReferencePrograms.All.Keys);

    [Theory]
    [MemberData(nameof(ReferenceProgramNames))]
    public void Compile_ReferenceProgram_MatchesGoldenFile(string name)
    {
        RobotProgram program = ReferencePrograms.Issue(name, RobotType.KUKA).Compile();

        Assert.Single(program.Files);
        GoldenFile.Check(program.Files[0], "KUKA");
    }

    [Fact]
    public void Compile_HelloRobotWithDeclaredTargets_MatchesGoldenSrcAndDat()
    {
        RobotProgram program = ReferencePrograms.Issue("HelloRobot", RobotType.KUKA).Compile(inlineTargets: false);

        Assert.Equal(["HelloRobot.src", "HelloRobot.dat"], program.Files.Select(f => f.FileName));
        GoldenFile.Check(program.Files[0], "KUKA", "targets");
        GoldenFile.Check(program.Files[1], "KUKA", "targets");
    }

    [Fact]
    public void Compile_HelloRobotWithoutHumanComments_MatchesGoldenFile()
    {
        RobotProgram program = ReferencePrograms.Issue("HelloRobot", RobotType.KUKA).Compile(humanComments: false);

        GoldenFile.Check(program.Files[0], "KUKA", "nocomments");
    }
}

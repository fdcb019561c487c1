using Machina.Tests.Brands.Kuka;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.GCode;

public class GCodeGoldenTests
{
    [Theory]
    [InlineData("HelloRobot", RobotType.ZMORPH)]
    [InlineData("SquarePushPop", RobotType.ZMORPH)]
    [InlineData("Rotations", RobotType.ZMORPH)]
    [InlineData("JointsToolsIO", RobotType.ZMORPH)]
    [InlineData("Print3D", RobotType.ZMORPH)]
    [InlineData("HelloRobot", RobotType.MARLIN)]
    [InlineData("SquarePushPop", RobotType.MARLIN)]
    [InlineData("Rotations", RobotType.MARLIN)]
    [InlineData("JointsToolsIO", RobotType.MARLIN)]
    [InlineData("Print3D", RobotType.MARLIN)]
    public void Compile_ReferenceProgram_MatchesGoldenFile(string name, RobotType brand)
    {
        RobotProgram program = ReferencePrograms.Issue(name, brand).Compile();

        Assert.Single(program.Files);
        Assert.Equal(name + ".gcode", program.Files[0].FileName);
        GoldenFile.Check(program.Files[0], brand.ToString());
    }
}

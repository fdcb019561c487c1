namespace Machina.Tests.Kinematics;

public class CatalogTableTests
{
    private const string Table = """
        # a comment
        brand KUKA
        source desc = ACME descriptions (example.org, abc1234)

        Arm 1 | 10 -20 300 400 500 60 | -170 -90 -180 -200 -120 -400 | 170 110 70 200 120 400 | 100 100 100 200 200 300 | @desc arm1.xacro; one note
        Arm 2 | 10 -20 300 400 500 60.5 | -170 -90 -180 -200 -120 -400 | 170 110 70 200 120 400 | - | Written by hand
        """;

    [Fact]
    public void Parse_Table_GivesEachArmItsNumbersAndSource()
    {
        RobotModel[] arms = CatalogTable.Parse("t.txt", Table);

        Assert.Equal(["Arm 1", "Arm 2"], arms.Select(a => a.Name));
        Assert.All(arms, a => Assert.Equal("KUKA", a.Brand));
        Assert.Equal(new OpwParameters(10, -20, 0, 300, 400, 500, 60), arms[0].Opw);
        Assert.Equal(60.5, arms[1].Opw!.Value.C4);
        Assert.Equal(new Joints(-170, -90, -180, -200, -120, -400), arms[0].MinJoints);
        Assert.Equal(new Joints(170, 110, 70, 200, 120, 400), arms[0].MaxJoints);
        Assert.Equal(new Joints(100, 100, 100, 200, 200, 300), arms[0].MaxJointSpeeds);
        Assert.Null(arms[1].MaxJointSpeeds);
        Assert.Equal("ACME descriptions (example.org, abc1234), arm1.xacro: joint origins, limits and velocities; one note", arms[0].Source);
        Assert.Equal("Written by hand", arms[1].Source);
    }

    [Theory]
    [InlineData("brand X\nA | 1 2 3 4 5 6 | 1 2 3 4 5 6 | 1 2 3 4 5 6 | -", "t.txt:2: 5 columns instead of 6")]
    [InlineData("brand X\n\nA | 1 2 3 4 5 | 1 2 3 4 5 6 | 1 2 3 4 5 6 | - | s", "t.txt:3: \"1 2 3 4 5\" has 5 numbers instead of 6")]
    [InlineData("brand X\nA | 1 2 3 4 5 x | 1 2 3 4 5 6 | 1 2 3 4 5 6 | - | s", "t.txt:2: \"x\" is not a number")]
    [InlineData("brand X\nA | 1 2 3 4 5 6 | 1 2 3 4 5 6 | 1 2 3 4 5 6 | - | @nobody a.xacro", "t.txt:2: the source \"@nobody a.xacro\" names no file")]
    [InlineData("A | 1 2 3 4 5 6 | 1 2 3 4 5 6 | 1 2 3 4 5 6 | - | s", "t.txt:1: an arm comes before the \"brand\" line")]
    public void Parse_MalformedLine_NamesTheFileLineAndFault(string text, string message)
    {
        var e = Assert.Throws<InvalidOperationException>(() => CatalogTable.Parse("t.txt", text));
        Assert.Contains(message, e.Message, StringComparison.Ordinal);
    }
}

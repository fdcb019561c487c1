namespace Machina.Tests.Core;

/// <summary>Robot.Create validation, brands, enum text overloads and robots living side by side.</summary>
public class RobotCreateTests
{
    [Theory]
    [InlineData(null)]
    [InlineData("")]
    [InlineData("   ")]
    [InlineData("1bot")]
    [InlineData("_bot")]
    public void Create_BadName_ThrowsNamingTheParameter(string? name)
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create(name!, "ABB"));
        var typed = Assert.Throws<ArgumentException>(() => Robot.Create(name!, RobotType.ABB));

        Assert.Equal("name", ex.ParamName);
        Assert.Equal("name", typed.ParamName);
        Assert.Contains("must start with a letter", ex.Message);
    }

    [Fact]
    public void Create_UnknownBrandText_ListsTheValidBrands()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "FANUC"));

        Assert.Equal("\"FANUC\" is not a valid robot brand; use one of: HUMAN, MACHINA, ABB, UR, KUKA, ZMORPH, MARLIN. (Parameter 'brand')", ex.Message);
        Assert.Equal("brand", ex.ParamName);
    }

    [Theory]
    [InlineData("2")]
    [InlineData("")]
    [InlineData("AB B")]
    public void Create_NumericOrEmptyBrandText_IsRefused(string brand)
    {
        Assert.Throws<ArgumentException>(() => Robot.Create("Bot", brand));
    }

    [Fact]
    public void Create_UndefinedBrandValue_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", (RobotType)42));

        Assert.Equal("brand", ex.ParamName);
    }

    [Theory]
    [InlineData("abb", RobotType.ABB)]
    [InlineData("Kuka", RobotType.KUKA)]
    [InlineData(" ur ", RobotType.UR)]
    [InlineData("marlin", RobotType.MARLIN)]
    public void Create_BrandTextAnyCase_IsAccepted(string text, RobotType brand)
    {
        var bot = Robot.Create("Ünïcode_Bot", text);

        Assert.Equal(brand, bot.Brand);
        Assert.True(bot.IsBrand(brand));
        Assert.True(bot.IsBrand(brand.ToString().ToLowerInvariant()));
        Assert.Equal("Ünïcode_Bot", bot.Name);
    }

    [Fact]
    public void Create_NoArguments_IsAHumanRobotNamedMachina()
    {
        var bot = Robot.Create();

        Assert.Equal("Robot[\"Machina\", HUMAN]", bot.ToString());
        Assert.Equal(RobotType.HUMAN, bot.Brand);
    }

    [Fact]
    public void ToString_NamedRobot_ShowsNameAndBrand()
    {
        Assert.Equal("Robot[\"HelloRobot\", ABB]", Robot.Create("HelloRobot", "ABB").ToString());
    }

    [Fact]
    public void MotionModeAndCoordinates_TextAnyCase_AreAccepted()
    {
        var bot = Robot.Create("Bot", RobotType.ABB);
        bot.MotionMode("JOINT");
        bot.Coordinates("local");

        Assert.Equal(MotionType.Joint, bot.GetCurrentMotionMode());
        Assert.Equal(ReferenceCS.Local, bot.GetCurrentReferenceCS());
    }

    [Theory]
    [InlineData("circular")]
    [InlineData("1")]
    [InlineData("")]
    public void MotionMode_BadText_ListsTheChoicesAndIssuesNothing(string text)
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        var ex = Assert.Throws<ArgumentException>(() => bot.MotionMode(text));

        Assert.Equal($"\"{text}\" is not a valid motion type; use one of: Linear, Joint. (Parameter 'motionType')", ex.Message);
        Assert.Equal("motionType", ex.ParamName);
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void Coordinates_BadText_ListsTheChoices()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", RobotType.ABB).Coordinates("tool"));

        Assert.Equal("\"tool\" is not a valid coordinate system; use one of: World, Local. (Parameter 'referenceCS')", ex.Message);
        Assert.Equal("referenceCS", ex.ParamName);
    }

    [Fact]
    public void ExternalAxisTo_BadTargetText_ListsTheChoices()
    {
        var ex = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", RobotType.ABB).ExternalAxisTo(1, 2, "both"));

        Assert.Equal("\"both\" is not a valid external axes target; use one of: All, Cartesian, Joint. (Parameter 'target')", ex.Message);
        Assert.Equal("target", ex.ParamName);
    }

    [Fact]
    public void TwoRobots_InOneProcess_HaveTheirOwnIdsStateAndLogs()
    {
        var a = Robot.Create("Alpha", RobotType.ABB);
        var b = Robot.Create("Beta", RobotType.UR);
        var logA = new List<LogEntry>();
        var logB = new List<LogEntry>();
        a.Logger.Logged += (_, e) => logA.Add(e);
        b.Logger.Logged += (_, e) => logB.Add(e);

        a.MoveTo(1, 2, 3);
        a.SpeedTo(99);
        b.MoveTo(7, 8, 9);
        Assert.Throws<ActionRefusedException>(() => a.PopSettings());

        Assert.Equal([1, 2], a.GetProgramActions().Select(x => x.Id));
        Assert.Equal([1], b.GetProgramActions().Select(x => x.Id));
        Assert.Equal(new Point(1, 2, 3), a.GetCurrentPosition());
        Assert.Equal(new Point(7, 8, 9), b.GetCurrentPosition());
        Assert.Equal(20, b.GetCurrentSpeed());
        LogEntry refusal = Assert.Single(logA);
        Assert.Equal("Alpha", refusal.Source);
        Assert.Equal(LogLevel.WARNING, refusal.Level);
        Assert.StartsWith("Refused PopSettings(); there are no saved settings", refusal.Message);
        Assert.Empty(logB);
    }
}

public class EnumTextTests
{
    [Theory]
    [InlineData("Linear, Joint")]
    [InlineData("Linear,Linear")]
    [InlineData("0")]
    [InlineData("-1")]
    [InlineData("Lin")]
    public void MotionMode_CombinedOrPartialNames_AreRefused(string text)
    {
        var bot = Robot.Create("Bot", RobotType.ABB);

        Assert.Throws<ArgumentException>(() => bot.MotionMode(text));
        Assert.Throws<InstructionParseException>(() => Instructions.Parse($"MotionMode(\"{text}\")"));
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void Create_CombinedBrandNames_AreRefused()
    {
        Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB, UR"));
    }
}

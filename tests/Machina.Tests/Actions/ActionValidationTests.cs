namespace Machina.Tests.Actions;

/// <summary>Constructor checks: bad numbers and texts are refused with an ArgumentException naming the parameter.</summary>
public class ActionValidationTests
{
    public static TheoryData<string, Func<RobotAction>> BadArguments() => new()
    {
        { "speed", () => new ActionSpeed(double.NaN, true) },
        { "speed", () => new ActionSpeed(double.PositiveInfinity, false) },
        { "speed", () => new ActionSpeed(-1, false) },
        { "speed", () => new ActionSpeed(0, false) },
        { "acceleration", () => new ActionAcceleration(double.NegativeInfinity, true) },
        { "acceleration", () => new ActionAcceleration(-0.5, false) },
        { "precision", () => new ActionPrecision(double.NaN, false) },
        { "precision", () => new ActionPrecision(-2, false) },
        { "translation", () => new ActionTranslation(new Vector(double.NaN, 0, 0), false) },
        { "translation", () => new ActionTranslation(new Vector(0, double.PositiveInfinity, 0), true) },
        { "axis", () => new ActionRotation(new Vector(0, 0, 0), 90, true) },
        { "axis", () => new ActionRotation(new Vector(double.NaN, 0, 1), 90, true) },
        { "angle", () => new ActionRotation(new Vector(0, 0, 1), double.NaN, true) },
        { "translation", () => new ActionTransformation(new Vector(0, 0, double.NaN), Rotation.Identity, true, true) },
        { "joints", () => new ActionAxes(new Joints(0, 0, double.NaN, 0, 0, 0), false) },
        { "through", () => new ActionArcMotion(new Plane(new Vector(double.NaN, 0, 0), Rotation.Identity), new Plane(Vector.XAxis, Rotation.Identity), false, true) },
        { "end", () => new ActionArcMotion(new Plane(Vector.YAxis, Rotation.Identity), new Plane(new Vector(0, 0, double.NegativeInfinity), Rotation.Identity), false, true) },
        { "relative", () => new ActionArcMotion(new Plane(Vector.YAxis, Rotation.Identity), new Plane(Vector.XAxis, Rotation.Identity), true, false) },
        { "axisNumber", () => new ActionExternalAxis(0, 1, ExternalAxesTarget.All, false) },
        { "axisNumber", () => new ActionExternalAxis(7, 1, ExternalAxesTarget.All, false) },
        { "value", () => new ActionExternalAxis(1, double.NaN, ExternalAxesTarget.All, false) },
        { "target", () => new ActionExternalAxis(1, 1, (ExternalAxesTarget)9, false) },
        { "angle", () => new ActionArmAngle(double.PositiveInfinity, false) },
        { "millis", () => new ActionWait(-1) },
        { "message", () => new ActionMessage(null!) },
        { "comment", () => new ActionComment(null!) },
        { "statement", () => new ActionCustomCode(null!, false) },
        { "statement", () => new ActionCustomCode("a\nb", false) },
        { "tool", () => new ActionDefineTool(null!) },
        { "name", () => new ActionAttachTool("") },
        { "name", () => new ActionAttachTool("1pen") },
        { "name", () => new ActionAttachTool("my pen") },
        { "pin", () => new ActionIODigital("", true, false) },
        { "pin", () => new ActionIODigital("DO 1", true, false) },
        { "pin", () => new ActionIOAnalog("A\"O", 1, false) },
        { "value", () => new ActionIOAnalog("1", double.NaN, false) },
        { "temperature", () => new ActionTemperature(double.NaN, RobotPartType.Bed, true, false) },
        { "temperature", () => new ActionTemperature(-1, RobotPartType.Bed, true, false) },
        { "part", () => new ActionTemperature(100, (RobotPartType)3, true, false) },
        { "rate", () => new ActionExtrusionRate(double.NaN, true) },
        { "rate", () => new ActionExtrusionRate(-0.1, false) },
        { "motionType", () => new ActionMotionMode((MotionType)5) },
        { "referenceCS", () => new ActionCoordinates((ReferenceCS)(-1)) },
    };

    [Theory]
    [MemberData(nameof(BadArguments))]
    public void Constructor_BadArgument_ThrowsNamingTheParameter(string parameter, Func<RobotAction> create)
    {
        var ex = Assert.ThrowsAny<ArgumentException>(create);
        Assert.Equal(parameter, ex.ParamName);
        Assert.False(string.IsNullOrWhiteSpace(ex.Message));
    }

    [Fact]
    public void Constructor_NaNSpeed_MessageSaysFinite()
    {
        var ex = Assert.Throws<ArgumentException>(() => new ActionSpeed(double.NaN, false));
        Assert.StartsWith("speed must be a finite number, but it was NaN.", ex.Message);
    }

    [Fact]
    public void Constructor_NegativeAbsoluteSpeed_MessageGivesTheValue()
    {
        var ex = Assert.Throws<ArgumentException>(() => new ActionSpeed(-5, false));
        Assert.StartsWith("Speed must be greater than 0 mm/s, but it was -5.", ex.Message);
    }

    [Fact]
    public void Constructor_NegativeRelativeValues_AreAccepted()
    {
        Assert.Equal(-5, new ActionSpeed(-5, true).Speed);
        Assert.Equal(-5, new ActionAcceleration(-5, true).Acceleration);
        Assert.Equal(-5, new ActionPrecision(-5, true).Precision);
        Assert.Equal(-5, new ActionExtrusionRate(-5, true).Rate);
        Assert.Equal(-5, new ActionTemperature(-5, RobotPartType.Chamber, false, true).Temperature);
        Assert.Equal(0, new ActionWait(0).Millis);
        Assert.Equal(0, new ActionAcceleration(0, false).Acceleration);
    }

    [Fact]
    public void Constructor_UnicodeToolName_IsAccepted()
    {
        Assert.Equal("Werkzeug_Ä1", new ActionAttachTool("Werkzeug_Ä1").ToolName);
    }
}

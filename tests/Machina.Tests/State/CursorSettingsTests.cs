namespace Machina.Tests.State;

/// <summary>Settings, the push/pop stack, external axes, arm angle, IO and temperatures.</summary>
public class CursorSettingsTests
{
    [Fact]
    public void Speed_RelativeAndAbsolute_AddOrSet()
    {
        var bot = Robot.Create("S", RobotType.ABB);
        bot.Speed(30);
        Assert.Equal(50, bot.GetCurrentSpeed());
        bot.SpeedTo(100);
        bot.Speed(-25);
        Assert.Equal(75, bot.GetCurrentSpeed());
        bot.AccelerationTo(500);
        bot.Acceleration(-100);
        Assert.Equal(400, bot.GetCurrentAcceleration());
        bot.PrecisionTo(1);
        bot.Precision(2.5);
        Assert.Equal(3.5, bot.GetCurrentPrecision());
    }

    [Fact]
    public void Speed_RelativeBelowZero_IsRefusedAndStateUnchanged()
    {
        var bot = Robot.Create("S", RobotType.ABB);

        var speed = Assert.Throws<ActionRefusedException>(() => bot.Speed(-20));
        var precision = Assert.Throws<ActionRefusedException>(() => bot.Precision(-6));

        Assert.Equal("the speed would become 0 mm/s; it must be greater than 0.", speed.Reason);
        Assert.Equal("the precision would become -1 mm; it must be 0 or more.", precision.Reason);
        Assert.Equal(20, bot.GetCurrentSpeed());
        Assert.Equal(5, bot.GetCurrentPrecision());
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void PopSettings_RestoresExactlyTheSixSettings()
    {
        var bot = PoseAssert.AtFlipped(0, 0, 0);
        bot.SpeedTo(50);
        bot.AccelerationTo(60);
        bot.PrecisionTo(2);
        bot.MotionMode(MotionType.Joint);
        bot.Coordinates(ReferenceCS.Local);
        bot.ExtrusionRateTo(0.5);
        bot.PushSettings();

        bot.SpeedTo(300);
        bot.AccelerationTo(900);
        bot.PrecisionTo(10);
        bot.MotionMode("linear");
        bot.Coordinates("world");
        bot.ExtrusionRateTo(2);
        bot.DefineTool("pen", new Vector(0, 0, 10), Rotation.Identity);
        bot.AttachTool("pen");
        bot.TemperatureTo(200, "extruder");
        bot.Extrude();
        bot.WriteDigital(1, true);
        bot.ExternalAxisTo(1, 10);
        bot.ArmAngleTo(15);
        bot.MoveTo(5, 5, 5);
        bot.PopSettings();

        RobotState s = bot.GetCurrentState();
        Assert.Equal(new Settings(50, 60, 2, MotionType.Joint, ReferenceCS.Local, 0.5), s.Settings);
        Assert.Equal("pen", s.Tool!.Name);
        Assert.Equal(200, s.ExtruderTemperature);
        Assert.True(s.IsExtruding);
        Assert.True(s.DigitalOutputs["1"]);
        Assert.Equal(10, s.ExternalAxesCartesian!.Value[1]);
        Assert.Equal(15, s.ArmAngle);
        Assert.Equal(new Vector(5, 5, 5), s.Position);
        Assert.Equal(0, s.SettingsDepth);
    }

    [Fact]
    public void PopSettings_Nested_RestoresInReverseOrder()
    {
        var bot = Robot.Create("Nest", RobotType.ABB);
        bot.SpeedTo(10);
        bot.PushSettings();
        bot.SpeedTo(20);
        bot.PushSettings();
        bot.SpeedTo(30);

        Assert.Equal(2, bot.GetCurrentState().SettingsDepth);
        bot.PopSettings();
        Assert.Equal(20, bot.GetCurrentSpeed());
        bot.PopSettings();
        Assert.Equal(10, bot.GetCurrentSpeed());
    }

    [Fact]
    public void PopSettings_EmptyStack_IsRefused()
    {
        var bot = Robot.Create("Pop", RobotType.ABB);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.PopSettings());

        Assert.Equal("Cannot apply \"PopSettings();\": there are no saved settings to restore; every PopSettings needs an earlier PushSettings.", ex.Message);
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void PushSettings_BeyondDepth1024_IsRefusedNotThrownAsCrash()
    {
        var bot = Robot.Create("Deep", RobotType.ABB);
        for (int i = 0; i < 1024; i++)
        {
            bot.PushSettings();
        }

        var ex = Assert.Throws<ActionRefusedException>(() => bot.PushSettings());

        Assert.Equal("more than 1024 PushSettings without a PopSettings; is a PopSettings missing?", ex.Reason);
        Assert.Equal(1024, bot.GetCurrentState().SettingsDepth);
        Assert.Equal(1024, bot.GetProgramActions().Count);
    }

    [Fact]
    public void ExternalAxis_RelativeOnUnsetAxis_IsRefused()
    {
        var bot = Robot.Create("Ext", RobotType.ABB);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.ExternalAxis(1, 5));

        Assert.Equal("cartesian external axis 1 has no value yet to change; use ExternalAxisTo first.", ex.Reason);
        Assert.Null(bot.GetCurrentExternalAxes());
    }

    [Fact]
    public void ExternalAxis_Targets_ChangeTheirOwnSets()
    {
        var bot = Robot.Create("Ext", RobotType.ABB);
        bot.ExternalAxisTo(1, 100);
        bot.ExternalAxisTo(2, 45, "Cartesian");
        bot.ExternalAxis(1, 5);
        bot.ExternalAxis(2, 5, "CARTESIAN");
        bot.ExternalAxisTo(3, -7, ExternalAxesTarget.Joint);

        RobotState s = bot.GetCurrentState();
        Assert.Equal(new ExternalAxes(105, 50), s.ExternalAxesCartesian);
        Assert.Equal(new ExternalAxes(105, null, -7), s.ExternalAxesJoints);
        Assert.Equal(s.ExternalAxesCartesian, bot.GetCurrentExternalAxes());
    }

    [Fact]
    public void ExternalAxis_RelativeJointOnlyCartesianSet_IsRefusedAndChangesNothing()
    {
        var bot = Robot.Create("Ext", RobotType.ABB);
        bot.ExternalAxisTo(2, 45, ExternalAxesTarget.Cartesian);

        var all = Assert.Throws<ActionRefusedException>(() => bot.ExternalAxis(2, 1));
        var joint = Assert.Throws<ActionRefusedException>(() => bot.ExternalAxis(2, 1, "joint"));

        Assert.Equal("joint external axis 2 has no value yet to change; use ExternalAxisTo first.", all.Reason);
        Assert.Equal(all.Reason, joint.Reason);
        Assert.Equal(new ExternalAxes(null, 45), bot.GetCurrentExternalAxes());
        Assert.Null(bot.GetCurrentState().ExternalAxesJoints);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(7)]
    [InlineData(-1)]
    public void ExternalAxisTo_AxisOutOfRange_IsAnArgumentError(int axis)
    {
        var bot = Robot.Create("Ext", RobotType.ABB);

        var ex = Assert.Throws<ArgumentOutOfRangeException>(() => bot.ExternalAxisTo(axis, 1));

        Assert.Equal("axisNumber", ex.ParamName);
        Assert.Empty(bot.GetProgramActions());
    }

    [Fact]
    public void ArmAngle_RelativeBeforeAbsolute_IsRefusedThenAdds()
    {
        var bot = Robot.Create("Arm", RobotType.ABB);

        var ex = Assert.Throws<ActionRefusedException>(() => bot.ArmAngle(5));
        bot.ArmAngleTo(30);
        bot.ArmAngle(-5);

        Assert.Equal("the arm angle has no value yet to change; use ArmAngleTo first.", ex.Reason);
        Assert.Equal(25, bot.GetCurrentState().ArmAngle);
    }

    [Fact]
    public void WriteDigitalAndAnalog_StorePerPinAndToolPinsSeparately()
    {
        var bot = Robot.Create("IO", RobotType.ABB);
        bot.WriteDigital(1, true);
        bot.WriteDigital("DO_15", false);
        bot.WriteDigital(1, false, toolPin: true);
        bot.WriteDigital("DO_15", true);
        bot.WriteAnalog(0, 0.25, toolPin: true);
        bot.WriteAnalog("AO_1", 3.5);

        RobotState s = bot.GetCurrentState();
        Assert.Equal(new Dictionary<string, bool> { ["1"] = true, ["DO_15"] = true, ["tool:1"] = false }, s.DigitalOutputs);
        Assert.Equal(new Dictionary<string, double> { ["tool:0"] = 0.25, ["AO_1"] = 3.5 }, s.AnalogOutputs);
    }

    [Fact]
    public void WriteDigital_NegativePinNumber_IsAnArgumentError()
    {
        var bot = Robot.Create("IO", RobotType.ABB);

        var ex = Assert.Throws<ArgumentOutOfRangeException>(() => bot.WriteDigital(-1, true));

        Assert.Equal("pinNumber", ex.ParamName);
    }

    [Fact]
    public void Temperature_PerPart_RelativeAddsAbsoluteSets()
    {
        var bot = Robot.Create("Printer", RobotType.ZMORPH);
        bot.TemperatureTo(200, "extruder");
        bot.Temperature(10, "EXTRUDER", false);
        bot.TemperatureTo(60, RobotPartType.Bed);

        RobotState s = bot.GetCurrentState();
        Assert.Equal((210.0, 60.0, 0.0), (s.ExtruderTemperature, s.BedTemperature, s.ChamberTemperature));
        var ex = Assert.Throws<ActionRefusedException>(() => bot.Temperature(-70, "bed"));
        Assert.Equal("the Bed temperature would become -10 C; it cannot be below 0 C.", ex.Reason);
        Assert.Equal(60, bot.GetCurrentState().BedTemperature);
    }

    [Fact]
    public void Temperature_UnknownPart_ListsTheParts()
    {
        var bot = Robot.Create("Printer", RobotType.ZMORPH);

        var ex = Assert.Throws<ArgumentException>(() => bot.TemperatureTo(200, "nozzle"));

        Assert.Equal("\"nozzle\" is not a valid printer part; use one of: Extruder, Bed, Chamber. (Parameter 'devicePart')", ex.Message);
        Assert.Equal("devicePart", ex.ParamName);
    }
}

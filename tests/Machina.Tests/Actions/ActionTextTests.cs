namespace Machina.Tests.Actions;

/// <summary>Exact human descriptions and instruction texts of every action (spec §4.2, with our lossless numbers).</summary>
public class ActionTextTests
{
    public static TheoryData<RobotAction, string, string> Texts() => new()
    {
        { new ActionSpeed(100, false), "Set motion speed to 100 mm/s or deg/s", "SpeedTo(100);" },
        { new ActionSpeed(25.5, true), "Increase motion speed by 25.5 mm/s or deg/s", "Speed(25.5);" },
        { new ActionSpeed(-50, true), "Decrease motion speed by -50 mm/s or deg/s", "Speed(-50);" },
        { new ActionAcceleration(200, false), "Set motion acceleration to 200 mm/s^2 or deg/s^2", "AccelerationTo(200);" },
        { new ActionAcceleration(-10, true), "Decrease motion acceleration by -10 mm/s^2 or deg/s^2", "Acceleration(-10);" },
        { new ActionPrecision(5, false), "Set precision radius to 5 mm", "PrecisionTo(5);" },
        { new ActionPrecision(2, true), "Increase precision radius by 2 mm", "Precision(2);" },
        { new ActionMotionMode(MotionType.Joint), "Set motion type to 'Joint'", "MotionMode(\"Joint\");" },
        { new ActionCoordinates(ReferenceCS.Local), "Set reference coordinate system to 'Local'", "Coordinates(\"Local\");" },
        { new ActionPushPop(true), "Push settings to buffer", "PushSettings();" },
        { new ActionPushPop(false), "Pop settings", "PopSettings();" },
        { new ActionTranslation(new Vector(400, 300, 500), false), "Move to [400, 300, 500] mm", "MoveTo(400,300,500);" },
        { new ActionTranslation(new Vector(0, 0, 250), true), "Move [0, 0, 250] mm", "Move(0,0,250);" },
        { new ActionTranslation(new Vector(0.1 + 0.2, -0.0, 1.23456), true), "Move [0.3, 0, 1.235] mm", "Move(0.30000000000000004,0,1.23456);" },
        { new ActionRotation(new Vector(0, 1, 0), -90, true), "Rotate -90 deg around [0, 1, 0]", "Rotate(0,1,0,-90);" },
        { new ActionRotation(new Vector(0, 0, 2), 45, true), "Rotate 45 deg around [0, 0, 1]", "Rotate(0,0,1,45);" },
        { new ActionRotation(Rotation.FromAxes(new Vector(-1, 0, 0), new Vector(0, 1, 0)), false),
            "Rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]", "RotateTo(-1,0,0,0,1,0);" },
        { new ActionTransformation(new Vector(300, 300, 300), Rotation.FromAxes(new Vector(-1, 0, 0), new Vector(0, 1, 0)), false, true),
            "Transform: move to [300, 300, 300] mm and rotate to [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]", "TransformTo(300,300,300,-1,0,0,0,1,0);" },
        { new ActionTransformation(new Vector(10, 0, 0), Rotation.FromAxisAngle(Vector.ZAxis, 90), true, true),
            "Transform: move [10, 0, 0] mm and rotate 90 deg around [0, 0, 1]", "Transform(10,0,0,0,0,1,90);" },
        { new ActionTransformation(new Vector(10, 0, 0), Rotation.FromAxisAngle(Vector.ZAxis, 90), true, false),
            "Transform: rotate 90 deg around [0, 0, 1] and move [10, 0, 0] mm", "Transform(10,0,0,0,0,1,90,False);" },
        { new ActionAxes(new Joints(0, 0, 0, 0, 90, 0), false), "Set joint rotations to [0, 0, 0, 0, 90, 0] deg", "AxesTo(0,0,0,0,90,0);" },
        { new ActionAxes(new Joints(1, -2, 3.5, 0, 0, 0), true), "Increase joint rotations by [1, -2, 3.5, 0, 0, 0] deg", "Axes(1,-2,3.5,0,0,0);" },
        { new ActionArcMotion(new Plane(new Vector(350, 350, 500), Rotation.Identity), new Plane(new Vector(400, 300, 500), Rotation.Identity), false, true),
            "Arc motion through [350, 350, 500] to [400, 300, 500]", "ArcMotionTo(350,350,500,400,300,500);" },
        { new ActionArcMotion(new Plane(new Vector(50, 50, 0), Rotation.Identity), new Plane(new Vector(100, 0, 0), Rotation.Identity), true, true),
            "Relative arc motion through [50, 50, 0] to [100, 0, 0]", "ArcMotion(50,50,0,100,0,0);" },
        { new ActionArcMotion(new Plane(new Vector(1, 2, 3), Rotation.Identity), new Plane(new Vector(4, 5, 6), Rotation.FlippedAroundY), false, false),
            "Arc motion through [1, 2, 3] [[1, 0, 0], [0, 1, 0], [0, 0, 1]] to [4, 5, 6] [[-1, 0, 0], [0, 1, 0], [0, 0, -1]]",
            "ArcMotionTo(1,2,3,1,0,0,0,1,0,4,5,6,-1,0,0,0,1,0);" },
        { new ActionExternalAxis(1, 100, ExternalAxesTarget.All, false), "Set external axis #1 to 100", "ExternalAxisTo(1,100);" },
        { new ActionExternalAxis(2, 45, ExternalAxesTarget.Cartesian, false), "Set external axis #2 to 45 for cartesian targets.", "ExternalAxisTo(2,45,\"Cartesian\");" },
        { new ActionExternalAxis(3, -5, ExternalAxesTarget.Joint, true), "Increase external axis #3 by -5 for joint targets.", "ExternalAxis(3,-5,\"Joint\");" },
        { new ActionArmAngle(30, false), "Set arm-angle to 30 deg", "ArmAngleTo(30);" },
        { new ActionArmAngle(-5, true), "Decrease arm-angle by -5 deg", "ArmAngle(-5);" },
        { new ActionWait(2000), "Wait 2000 ms", "Wait(2000);" },
        { new ActionMessage("Hello Robot!"), "Display message \"Hello Robot!\"", "Message(\"Hello Robot!\");" },
        { new ActionMessage("say \"hi\" \\ now"), "Display message \"say \"hi\" \\ now\"", "Message(\"say \\\"hi\\\" \\\\ now\");" },
        { new ActionComment("a\nb"), "Comment: \"a\nb\"", "Comment(\"a\\nb\");" },
        { new ActionCustomCode("x := 1;", false), "Add custom instruction: \"x := 1;\"", "CustomCode(\"x := 1;\",False);" },
        { new ActionCustomCode("VAR num x;", true), "Add custom declaration: \"VAR num x;\"", "CustomCode(\"VAR num x;\",True);" },
        { new ActionDefineTool(Tool.Create("pen", new Vector(0, 0, 50), Rotation.Identity)), "Define tool \"pen\" on the Robot.",
            "DefineTool(\"pen\",0,0,50,1,0,0,0,1,0,1,0,0,25);" },
        { new ActionAttachTool("pen"), "Attach tool \"pen\" to robot flange.", "AttachTool(\"pen\");" },
        { new ActionDetachTool(), "Detach all tools from robot.", "DetachTool();" },
        { new ActionIODigital("DO_15", false, false), "Turn digital IO \"DO_15\" OFF", "WriteDigital(\"DO_15\",False);" },
        { new ActionIODigital("2", true, true), "Turn tool digital IO 2 ON", "WriteDigital(2,True,True);" },
        { new ActionIOAnalog("0", 0.25, true), "Set tool analog IO 0 to 0.25", "WriteAnalog(0,0.25,True);" },
        { new ActionIOAnalog("AO_1", 3, false), "Set analog IO \"AO_1\" to 3", "WriteAnalog(\"AO_1\",3);" },
        { new ActionTemperature(200, RobotPartType.Extruder, true, false), "Set Extruder temperature to 200 C and wait", "TemperatureTo(200,\"Extruder\",True);" },
        { new ActionTemperature(-10.4, RobotPartType.Bed, false, true), "Decrease Bed temperature by -10 C", "Temperature(-10.4,\"Bed\",False);" },
        { new ActionExtrusion(true), "Turn extrusion on", "Extrude(True);" },
        { new ActionExtrusion(false), "Turn extrusion off", "Extrude(False);" },
        { new ActionExtrusionRate(0.05, false), "Set extrusion rate to 0.05 mm/mm", "ExtrusionRateTo(0.05);" },
        { new ActionExtrusionRate(0.01, true), "Increase extrusion rate by 0.01 mm/mm", "ExtrusionRate(0.01);" },
        { new ActionInitialization(true), "Initialize this device.", "Initialize();" },
        { new ActionInitialization(false), "Terminate this device.", "Terminate();" },
    };

    [Theory]
    [MemberData(nameof(Texts))]
    public void Describe_EveryAction_GivesExactText(RobotAction action, string description, string instruction)
    {
        Assert.Equal(description, action.Describe());
        Assert.Equal(description, action.ToString());
        Assert.Equal(instruction, action.ToInstruction());
    }

    [Theory]
    [MemberData(nameof(Texts))]
    public void Parse_EveryActionInstruction_GivesAnEqualAction(RobotAction action, string description, string instruction)
    {
        _ = description;
        RobotAction parsed = Assert.Single(Instructions.Parse(instruction));
        Assert.Equal(action, parsed);
        Assert.Equal(instruction, parsed.ToInstruction());
    }

    [Fact]
    public void Type_EveryActionClass_MatchesItsActionType()
    {
        var pairs = Texts().Select(row => (RobotAction)row[0]).Select(a => (a.GetType().Name, a.Type.ToString())).Distinct().ToArray();

        Assert.Equal(26, pairs.Length);
        Assert.All(pairs, p => Assert.Equal("Action" + p.Item2, p.Item1));
    }

    [Fact]
    public void Id_NewAction_IsMinusOne()
    {
        Assert.Equal(-1, new ActionWait(5).Id);
        Assert.False(new ActionWait(5).IsRelative);
        Assert.True(new ActionSpeed(5, true).IsRelative);
        Assert.False(new ActionSpeed(5, false).IsRelative);
    }

    [Fact]
    public void IsDigit_IOPins_NumberOrName()
    {
        var numbered = new ActionIODigital("7", true, false);
        var named = new ActionIOAnalog("AO_1", 1, false);

        Assert.True(numbered.IsDigit);
        Assert.Equal(7, numbered.PinNumber);
        Assert.False(named.IsDigit);
        Assert.Equal(-1, named.PinNumber);
    }

    [Theory]
    [InlineData(0.00001, 0, 0, 1, "Rotate 1E-05 deg around [0, 0, 1]", "Rotate(0,0,1,1E-05);")]
    [InlineData(-0.954, 0, 0, 1, "Rotate -0.954 deg around [0, 0, 1]", "Rotate(0,0,1,-0.954);")]
    [InlineData(1e20, 1, 1, 0, "Rotate 1E+20 deg around [0.707, 0.707, 0]", "Rotate(0.7071067811865475,0.7071067811865475,0,1E+20);")]
    [InlineData(1.0 / 3, 0, -2, 0, "Rotate 0.333333333333333 deg around [0, -1, 0]", "Rotate(0,-1,0,0.3333333333333333);")]
    [InlineData(-0.0, 3, 4, 0, "Rotate 0 deg around [0.6, 0.8, 0]", "Rotate(0.6,0.8,0,0);")]
    public void Describe_RelativeRotation_WrittenWithoutAStringAsTheGeneralFormatWrites(double angle, double x, double y, double z,
                                                                                         string description, string instruction)
    {
        var action = new ActionRotation(new Vector(x, y, z), angle, true);
        Span<char> buffer = stackalloc char[RobotAction.MaxWrittenInstructionChars + RobotAction.MaxWrittenDescriptionChars];

        Assert.Equal(description, action.Describe());
        Assert.Equal(description, new string(buffer[..action.TryWriteDescription(buffer)]));
        Assert.Equal($"Rotate {Num.G(angle)} deg around {action.Request.Axis}", description);
        Assert.Equal(instruction, action.ToInstruction());
        Assert.Equal(instruction, new string(buffer[..action.TryWriteInstruction(buffer)]));
    }

    [Fact]
    public void TryWriteDescription_AbsoluteRotationOrOtherActions_LeavesItToDescribe()
    {
        Span<char> buffer = stackalloc char[RobotAction.MaxWrittenDescriptionChars];

        Assert.Equal(-1, new ActionRotation(Rotation.FlippedAroundY, false).TryWriteDescription(buffer));
        Assert.Equal(-1, new ActionRotation(Rotation.FlippedAroundY, false).TryWriteInstruction(buffer));
        Assert.Equal(-1, new ActionWait(5).TryWriteDescription(buffer));
        Assert.Equal("Move [1, 2, 3] mm", new string(buffer[..new ActionTranslation(new Vector(1, 2, 3), true).TryWriteDescription(buffer)]));
    }
}

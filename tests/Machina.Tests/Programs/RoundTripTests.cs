namespace Machina.Tests.Programs;

/// <summary>Every action's instruction parses back to an equal action, also for awkward numbers and strings.</summary>
public class RoundTripTests
{
    private static readonly double[] TrickyNumbers = [-0.0, 1e-9, 1e300, -1e300, 0.1 + 0.2, 1.0 / 3, double.Epsilon, 123456789.123456789, -7.25];

    private static readonly string[] TrickyStrings =
    [
        "", "say \"hi\"", "back\\slash", "two\nlines", "crlf\r\nend", "tab\there", "unicodé ✓ 日本 🤖", "f(x, y)", "a, b, c",
        "not // a comment", "ends with \\", "\"", "semi; colon", "bell\u0007",
    ];

    public static IEnumerable<object[]> NumericActions()
    {
        foreach (double v in TrickyNumbers)
        {
            double positive = Math.Abs(v) > 0 ? Math.Abs(v) : 1;
            yield return [new ActionSpeed(v, true)];
            yield return [new ActionSpeed(positive, false)];
            yield return [new ActionAcceleration(v, true)];
            yield return [new ActionAcceleration(Math.Abs(v), false)];
            yield return [new ActionPrecision(v, true)];
            yield return [new ActionPrecision(Math.Abs(v), false)];
            yield return [new ActionTranslation(new Vector(v, -v, v * 0.5), true)];
            yield return [new ActionTranslation(new Vector(v, 1, 2), false)];
            yield return [new ActionAxes(new Joints(v, 1, 2, 3, 4, v), true)];
            yield return [new ActionAxes(new Joints(0, v, 0, 0, 0, 0), false)];
            yield return [new ActionExternalAxis(6, v, ExternalAxesTarget.Joint, true)];
            yield return [new ActionExternalAxis(1, v, ExternalAxesTarget.All, false)];
            yield return [new ActionArmAngle(v, true)];
            yield return [new ActionArmAngle(v, false)];
            yield return [new ActionIOAnalog("3", v, true)];
            yield return [new ActionTemperature(v, RobotPartType.Chamber, false, true)];
            yield return [new ActionTemperature(Math.Abs(v), RobotPartType.Extruder, true, false)];
            yield return [new ActionExtrusionRate(v, true)];
            yield return [new ActionExtrusionRate(Math.Abs(v), false)];
            yield return [new ActionTransformation(new Vector(v, 2, 3), Rotation.FromAxisAngle(new Vector(1, 2, 3), 37), true, false)];
            yield return [new ActionTransformation(new Vector(1, v, 3), Rotation.FromAxisAngle(new Vector(-1, 0, 3), 170), false, true)];
            yield return [new ActionArcMotion(new Plane(new Vector(v, 1, 0), Rotation.Identity), new Plane(new Vector(2, v, 5), Rotation.Identity), false, true)];
            yield return [new ActionDefineTool(Tool.Create("t", v, 1, 2, 0, 1, 0, -1, 0, 0, Math.Abs(v), v, 0, 1))];
        }
    }

    public static IEnumerable<object[]> OtherActions()
    {
        foreach (string s in TrickyStrings)
        {
            yield return [new ActionMessage(s)];
            yield return [new ActionComment(s)];
            if (!s.Contains('\n') && !s.Contains('\r'))
            {
                yield return [new ActionCustomCode(s, true)];
            }
        }
        yield return [new ActionRotation(new Vector(0.3, -0.4, 12), 1e-9, true)];
        yield return [new ActionRotation(new Vector(1, 1, 1), -179.999, true)];
        yield return [new ActionRotation(Rotation.FromYawPitchRoll(10, 20, 30), false)];
        yield return [new ActionRotation(Rotation.FromAxisAngle(1, 0, 0, 180), false)];
        yield return [new ActionRotation(Rotation.FromAxisAngle(2, -1, 0.5, 77.7), true)];
        yield return [new ActionArcMotion(new Plane(new Vector(1, 2, 3), Rotation.FromAxisAngle(0, 0, 1, 33)), new Plane(new Vector(4, 5, 6), Rotation.FromYawPitchRoll(1, 2, 3)), false, false)];
        yield return [new ActionArcMotion(new Plane(new Vector(1, 1, 0), Rotation.Identity), new Plane(new Vector(2, 0, 0), Rotation.Identity), true, true)];
        yield return [new ActionIODigital("02", true, false)];
        yield return [new ActionIODigital("9999999999", false, true)];
        yield return [new ActionIODigital("DO-1.a", true, true)];
        yield return [new ActionIOAnalog("007", 1, false)];
        yield return [new ActionWait(long.MaxValue)];
        yield return [new ActionMotionMode(MotionType.Linear)];
        yield return [new ActionCoordinates(ReferenceCS.World)];
        yield return [new ActionExternalAxis(4, 2, ExternalAxesTarget.Cartesian, false)];
        yield return [new ActionAttachTool("Ñandú_2")];
        yield return [new ActionDefineTool(Tool.Create("rot", new Vector(0, 50, 0), Rotation.FromAxisAngle(0, 0, 1, 90), 2.5, new Vector(0, 20, 0)))];
    }

    [Theory]
    [MemberData(nameof(NumericActions))]
    [MemberData(nameof(OtherActions))]
    public void Parse_ToInstruction_GivesAnEqualAction(RobotAction action)
    {
        string text = action.ToInstruction();

        RobotAction parsed = Assert.Single(Instructions.Parse(text));

        Assert.Equal(action, parsed);
        if (action is not (ActionRotation or ActionTransformation or ActionArcMotion or ActionDefineTool))
        {
            // Orientations are compared within 1e-9 degrees: rebuilding a rotation from printed axes may change the last bit.
            Assert.Equal(text, parsed.ToInstruction());
        }
    }

    [Fact]
    public void Parse_NegativeZero_PrintsZeroAndParsesBack()
    {
        var action = new ActionTranslation(new Vector(-0.0, -0.0, -0.0), true);

        Assert.Equal("Move(0,0,0);", action.ToInstruction());
        Assert.Equal(action, Instructions.Parse(action.ToInstruction())[0]);
    }

    [Fact]
    public void Parse_LosslessNumbers_KeepEveryBit()
    {
        var action = new ActionTranslation(new Vector(0.1 + 0.2, 1e-9, 1e300), false);
        var parsed = (ActionTranslation)Instructions.Parse(action.ToInstruction())[0];

        Assert.Equal("MoveTo(0.30000000000000004,1E-09,1E+300);", action.ToInstruction());
        Assert.Equal(BitConverter.DoubleToInt64Bits(0.1 + 0.2), BitConverter.DoubleToInt64Bits(parsed.Translation.X));
    }

    [Fact]
    public void Parse_AllActionsInOneText_GivesTheSameSequence()
    {
        RobotAction[] all = [.. NumericActions().Concat(OtherActions()).Select(row => (RobotAction)row[0])];
        string text = string.Join("\n", all.Select(a => a.ToInstruction()));

        Assert.Equal(all, Instructions.Parse(text));
        Assert.Equal(all, Instructions.Parse(string.Concat(all.Select(a => a.ToInstruction()))));
    }
}

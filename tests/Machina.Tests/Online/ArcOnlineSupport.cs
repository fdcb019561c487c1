using Machina.Simulation.Twin;

namespace Machina.Tests.Online;

/// <summary>
/// One program streamed online and the same program compiled, each run on the same brand's twin: where each arm ended, and the
/// check that both ends agree within 0.01 mm and 0.01° (issue 46: online equals offline).
/// </summary>
internal static class ArcOnlineSupport
{
    /// <summary>Largest distance accepted between the two ends, in mm.</summary>
    internal const double PositionToleranceMm = 0.01;

    /// <summary>Largest angle accepted between the two tool orientations, and between any two joints, in degrees.</summary>
    internal const double AngleToleranceDegrees = 0.01;

    /// <summary>Issues every action of <paramref name="program"/> (Machina instructions) on <paramref name="bot"/>, in order.</summary>
    internal static void IssueAll(Robot bot, string program)
    {
        foreach (RobotAction action in Instructions.Parse(program))
        {
            Assert.True(bot.Issue(action), action.ToInstruction());
        }
    }

    /// <summary>The files <paramref name="brand"/>'s compiler writes for <paramref name="program"/> on <paramref name="model"/>, as (name, text).</summary>
    internal static List<(string Name, string Text)> Compile(RobotType brand, string program, RobotModel model)
    {
        RobotProgram compiled = Compilers.For(brand).Compile(new CompileJob("Program", Instructions.Parse(program), CompileOptions.Default) { Model = model });
        return [.. compiled.Files.Select(f => (f.FileName, f.ToText("\n")))];
    }

    /// <summary>Asserts that the arm ended at the same TCP pose and joints online and offline.</summary>
    internal static void AssertSameEnd(TwinArm offline, TwinArm online)
    {
        Pose expected = offline.Tcp, actual = online.Tcp;
        double distance = (actual.Position - expected.Position).Length;
        double turn = TwinRotation.AngleDegrees(expected.Rotation, actual.Rotation);
        Joints joints = online.Joints - offline.Joints;
        double worstJoint = Enumerable.Range(0, Joints.Count).Max(i => Math.Abs(joints[i]));
        string report = $"offline TCP {expected.Position} joints {offline.Joints}; online TCP {actual.Position} joints {online.Joints}";
        Assert.True(distance <= PositionToleranceMm, $"{distance} mm apart: {report}");
        Assert.True(turn <= AngleToleranceDegrees, $"{turn}° apart: {report}");
        Assert.True(worstJoint <= AngleToleranceDegrees, $"a joint {worstJoint}° apart: {report}");
    }
}

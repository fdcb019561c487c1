using System.Globalization;
using System.Text.RegularExpressions;
using Machina.Tests.Support;

namespace Machina.Tests.Programs;

/// <summary>The same program compiled for every brand reaches the same targets, once each language's units are converted back.</summary>
public class CrossBrandTargetTests
{
    private static readonly string Num = @"(-?[0-9.]+(?:E[-+]?[0-9]+)?)";

    private static double D(Group g) => double.Parse(g.Value, CultureInfo.InvariantCulture);

    /// <summary>The Cartesian targets the cursor reaches, one per Cartesian motion action, in order.</summary>
    private static List<(Vector Position, Rotation Rotation)> Expected(string program)
    {
        var bot = Robot.Create(program, RobotType.MACHINA);
        var targets = new List<(Vector, Rotation)>();
        bot.ActionIssued += (_, e) =>
        {
            if (e.LastAction is ActionTranslation or ActionRotation or ActionTransformation && e.Position is Vector p && e.Rotation is Rotation r)
            {
                targets.Add((p, r));
            }
        };
        ReferencePrograms.All[program](bot);
        return targets;
    }

    private static string Compiled(string program, RobotType brand, string extension) =>
        Robot.Create(program, brand).Let(b => { ReferencePrograms.All[program](b); return b; }).Compile().GetFile(extension)!.ToText();

    public static TheoryData<string> Programs => new() { "HelloRobot", "SquarePushPop", "Rotations" };

    [Theory]
    [MemberData(nameof(Programs))]
    public void Rapid_TargetsMatchTheCursor(string program)
    {
        var expected = Expected(program);
        var matches = Regex.Matches(Compiled(program, RobotType.ABB, "mod"),
            $@"Move[LJ] \[\[{Num}, {Num}, {Num}\], \[{Num}, {Num}, {Num}, {Num}\]");

        Assert.Equal(expected.Count, matches.Count);
        for (int i = 0; i < matches.Count; i++)
        {
            var g = matches[i].Groups;
            AssertClose(expected[i].Position, new Vector(D(g[1]), D(g[2]), D(g[3])), 1e-3);
            AssertSameRotation(expected[i].Rotation, Rotation.FromQuaternion(D(g[4]), D(g[5]), D(g[6]), D(g[7])), 0.02);
        }
    }

    [Theory]
    [MemberData(nameof(Programs))]
    public void UrScript_TargetsMatchTheCursorInMetresAndRadians(string program)
    {
        var expected = Expected(program);
        var matches = Regex.Matches(Compiled(program, RobotType.UR, "script"),
            $@"move[lp]\(p\[{Num},{Num},{Num},{Num},{Num},{Num}\]");

        Assert.Equal(expected.Count, matches.Count);
        for (int i = 0; i < matches.Count; i++)
        {
            var g = matches[i].Groups;
            AssertClose(expected[i].Position, new Vector(D(g[1]), D(g[2]), D(g[3])) * 1000, 1e-3);
            var rv = new Vector(D(g[4]), D(g[5]), D(g[6])) * (180 / Math.PI);
            AssertSameRotation(expected[i].Rotation, Rotation.FromRotationVector(rv), 1e-3);
        }
    }

    [Theory]
    [MemberData(nameof(Programs))]
    public void Krl_TargetsMatchTheCursorAsZyxEulerAngles(string program)
    {
        var expected = Expected(program);
        var matches = Regex.Matches(Compiled(program, RobotType.KUKA, "src"),
            $@"LIN \{{E6POS: X {Num}, Y {Num}, Z {Num}, A {Num}, B {Num}, C {Num}");

        Assert.Equal(expected.Count, matches.Count);
        for (int i = 0; i < matches.Count; i++)
        {
            var g = matches[i].Groups;
            AssertClose(expected[i].Position, new Vector(D(g[1]), D(g[2]), D(g[3])), 1e-3);
            AssertSameRotation(expected[i].Rotation, Rotation.FromYawPitchRoll(D(g[4]), D(g[5]), D(g[6])), 1e-3);
        }
    }

    [Theory]
    [InlineData("SquarePushPop", RobotType.ZMORPH)]
    [InlineData("SquarePushPop", RobotType.MARLIN)]
    [InlineData("HelloRobot", RobotType.ZMORPH)]
    public void GCode_PositionsMatchTheCursor(string program, RobotType brand)
    {
        var expected = Expected(program).Select(t => t.Position).Distinct().ToList();
        var matches = Regex.Matches(Compiled(program, brand, "gcode"), $@"^G[01] X{Num} Y{Num} Z{Num}", RegexOptions.Multiline);
        var positions = matches.Select(m => new Vector(D(m.Groups[1]), D(m.Groups[2]), D(m.Groups[3]))).Distinct().ToList();

        Assert.Equal(expected.Count, positions.Count);
        for (int i = 0; i < positions.Count; i++)
        {
            AssertClose(expected[i], positions[i], 1e-3);
        }
    }

    private static void AssertClose(Vector expected, Vector actual, double tolerance) =>
        Assert.True(Vector.Distance(expected, actual) <= tolerance, $"expected {expected}, got {actual}");

    private static void AssertSameRotation(Rotation expected, Rotation actual, double toleranceDegrees) =>
        Assert.True(expected.IsSimilar(actual, toleranceDegrees), $"expected {expected}, got {actual} ({expected.AngleTo(actual)} deg apart)");
}

internal static class FunctionalExtensions
{
    internal static TResult Let<T, TResult>(this T value, Func<T, TResult> f) => f(value);
}

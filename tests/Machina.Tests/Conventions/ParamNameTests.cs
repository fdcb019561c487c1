using System.Reflection;

namespace Machina.Tests.Conventions;

/// <summary>The docs promise that an <see cref="ArgumentException"/> from a verb names the parameter of the method called.</summary>
public class ParamNameTests
{
    /// <summary>A valid value for a parameter, or null when the test has none (such methods are skipped).</summary>
    private static object? Good(ParameterInfo p) => p.ParameterType switch
    {
        Type t when t == typeof(double) => AxisComponent(p.Name!) ?? 1.0,
        Type t when t == typeof(int) => 1,
        Type t when t == typeof(long) => 1L,
        Type t when t == typeof(bool) => false,
        Type t when t == typeof(Vector) => new Vector(1, 0, 0),
        Type t when t == typeof(Rotation) => Rotation.Identity,
        Type t when t == typeof(Joints) => new Joints(0, 0, 0, 0, 0, 0),
        Type t when t == typeof(RobotModel) => RobotModels.Get("IRB 120"),
        Type t when t.IsEnum => p.Name == "brand" ? RobotType.ABB : Enum.GetValues(t).GetValue(0),
        Type t when t == typeof(string) => p.Name switch
        {
            "brand" => "ABB",
            "model" => "IRB 120",
            "target" => "All",
            "devicePart" => "extruder",
            "motionType" => "linear",
            "referenceCS" => "world",
            "mode" => "offline",
            "type" => "Machina",
            _ => "Bot",
        },
        _ => null,
    };

    /// <summary>Frame axes given as numbers get the world X and Y axes (all ones would be parallel, an error of their own).</summary>
    private static double? AxisComponent(string name) => name switch
    {
        _ when name.Contains("XAxis", StringComparison.Ordinal) || name.Contains("_vX", StringComparison.Ordinal) =>
            name.EndsWith('X') || name.EndsWith('0') ? 1 : 0,
        _ when name.Contains("YAxis", StringComparison.Ordinal) || name.Contains("_vY", StringComparison.Ordinal) =>
            name.EndsWith('Y') || name.EndsWith('1') ? 1 : 0,
        _ => null,
    };

    private static IEnumerable<object?> Bad(Type t)
    {
        if (t == typeof(double)) { yield return double.NaN; }
        if (t == typeof(string)) { yield return null; yield return "no such 9"; }
        if (t == typeof(Vector)) { yield return new Vector(double.NaN, 0, 0); }
        if (t == typeof(int) || t == typeof(long)) { yield return Convert.ChangeType(-1, t, System.Globalization.CultureInfo.InvariantCulture); }
        if (t.IsEnum) { yield return Enum.ToObject(t, 999); }
    }

    [Theory]
    [InlineData(typeof(Robot), 100)]
    [InlineData(typeof(Tool), 20)]
    public void PublicMethods_BadArgument_ParamNameIsTheParameterOfTheMethodCalled(Type type, int atLeast)
    {
        var wrong = new List<string>();
        int checkedCount = 0;
        foreach (MethodInfo m in type.GetMethods(BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly))
        {
            if (m.IsSpecialName || m.Name.Contains("Connect", StringComparison.Ordinal) || m.ReturnType.IsAssignableTo(typeof(Task))
                || m.GetCustomAttribute<ObsoleteAttribute>() is not null)
            {
                continue;
            }
            ParameterInfo[] ps = m.GetParameters();
            object?[] good = ps.Select(Good).ToArray();
            if (good.Any(g => g is null))
            {
                continue;
            }
            for (int i = 0; i < ps.Length; i++)
            {
                foreach (object? bad in Bad(ps[i].ParameterType))
                {
                    object?[] args = (object?[])good.Clone();
                    args[i] = bad;
                    Robot bot = Robot.Create("Bot", "ABB");
                    try
                    {
                        m.Invoke(m.IsStatic ? null : type == typeof(Robot) ? bot : Tool.Create("T", new Vector(0, 0, 100), Rotation.Identity), args);
                    }
                    catch (TargetInvocationException e) when (e.InnerException is ArgumentException ae)
                    {
                        checkedCount++;
                        if (ae.ParamName != ps[i].Name)
                        {
                            wrong.Add($"{m.Name}({string.Join(", ", ps.Select(p => p.Name))}) with {ps[i].Name} = {bad ?? "null"}: ParamName {ae.ParamName ?? "null"}");
                        }
                    }
                    catch (TargetInvocationException)
                    {
                        // Not an argument error (e.g. a refusal because of the robot's state): not what this test is about.
                    }
                }
            }
        }
        Assert.True(checkedCount > atLeast, $"only {checkedCount} argument errors were provoked");
        Assert.True(wrong.Count == 0, string.Join("\n", wrong));
    }

    [Fact]
    public void MoveTo_NaNInY_NamesYAndSaysWhy()
    {
        var e = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB").MoveTo(1, double.NaN, 3));
        Assert.Equal("y", e.ParamName);
        Assert.StartsWith("y must be a finite number, but it was NaN.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Axes_NaNInJoints_NamesIncrements()
    {
        // Found by the extreme-value test: it named "joints", a parameter of AxesTo.
        var e = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB").Axes(new Joints(0, double.NaN, 0, 0, 0, 0)));
        Assert.Equal("increments", e.ParamName);
        Assert.StartsWith("increments must contain six finite numbers.", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void RotateTo_ZeroOrParallelAxes_NamesTheAxis()
    {
        // Found by the extreme-value test: these errors named no parameter at all.
        var zero = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB").RotateTo(Vector.Zero, Vector.YAxis));
        var parallel = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB").RotateTo(Vector.XAxis, new Vector(1e308, 0, 0)));
        var direct = Assert.Throws<ArgumentException>(() => Rotation.FromAxes(Vector.XAxis, Vector.Zero));

        Assert.Equal(("xAxis", "yAxis", "yAxis"), (zero.ParamName, parallel.ParamName, direct.ParamName));
        Assert.StartsWith("Cannot build a frame from X [0, 0, 0] and Y [0, 1, 0]: an axis is zero.", zero.Message, StringComparison.Ordinal);
        Assert.StartsWith("Cannot build a frame from X [1, 0, 0] and Y [1E+308, 0, 0]: the axes are parallel.", parallel.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void Wait_Negative_NamesTimeMillisAndKeepsTheMessage()
    {
        var e = Assert.Throws<ArgumentOutOfRangeException>(() => Robot.Create("Bot", "ABB").Wait(-5));
        Assert.Equal("timeMillis", e.ParamName);
        Assert.Equal(-5L, e.ActualValue);
        Assert.StartsWith("A wait cannot be negative; give milliseconds, 0 or more. (Parameter 'timeMillis')", e.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void MotionMode_UnknownText_NamesMotionType()
    {
        var e = Assert.Throws<ArgumentException>(() => Robot.Create("Bot", "ABB").MotionMode("sideways"));
        Assert.Equal("motionType", e.ParamName);
        Assert.Contains("\"sideways\" is not a valid motion type", e.Message, StringComparison.Ordinal);
    }
}

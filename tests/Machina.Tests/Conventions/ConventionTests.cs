using System.Reflection;
using System.Text.RegularExpressions;

namespace Machina.Tests.Conventions;

public class ConventionTests
{
    private static readonly Assembly Library = typeof(Robot).Assembly;

    [Fact]
    public void PublicTypes_AllLiveInTheMachinaNamespace()
    {
        var outside = Library.GetExportedTypes().Where(t => t.Namespace != "Machina").Select(t => t.FullName).ToArray();

        Assert.Empty(outside);
    }

    [Fact]
    public void PublicConcreteClasses_AreSealed()
    {
        var unsealed = Library.GetExportedTypes()
            .Where(t => t.IsClass && !t.IsAbstract && !t.IsSealed && !typeof(Delegate).IsAssignableFrom(t))
            .Select(t => t.Name).ToArray();

        Assert.Empty(unsealed);
    }

    [Fact]
    public void RelativeVerbs_EachHaveAnAbsoluteTwin()
    {
        string[] names = typeof(Robot).GetMethods(BindingFlags.Public | BindingFlags.Instance).Select(m => m.Name).Distinct().ToArray();
        string[] relative = ["Move", "Rotate", "Transform", "Axes", "ExternalAxis", "Speed", "Acceleration", "Precision",
            "Temperature", "ExtrusionRate", "ArcMotion", "ArmAngle"];

        foreach (string verb in relative)
        {
            Assert.Contains(verb, names);
            Assert.Contains(verb + "To", names);
        }
    }

    [Fact]
    public void EveryActionType_IsSealedAndHasAnActionTypeValue()
    {
        var actionTypes = Library.GetExportedTypes().Where(t => t.IsSubclassOf(typeof(RobotAction))).ToArray();

        Assert.Equal(28, actionTypes.Length);
        Assert.All(actionTypes, t => Assert.True(t.IsSealed, t.Name));
    }

    [Fact]
    public void LibrarySource_UsesNoWallClockSleepOrConsole()
    {
        string src = Path.Combine(RepositoryRoot(), "src");
        var forbidden = new Regex(@"DateTime\.(Now|UtcNow)|Thread\.Sleep|Console\.(Write|Read)", RegexOptions.Compiled);
        var offenders = Directory.EnumerateFiles(src, "*.cs", SearchOption.AllDirectories)
            .Where(f => !f.Contains($"{Path.DirectorySeparatorChar}obj{Path.DirectorySeparatorChar}"))
            .Where(f => forbidden.IsMatch(File.ReadAllText(f)))
            .Select(Path.GetFileName).ToArray();

        Assert.Empty(offenders);
    }

    internal static string RepositoryRoot()
    {
        var dir = new DirectoryInfo(AppContext.BaseDirectory);
        while (dir is not null && !File.Exists(Path.Combine(dir.FullName, "Machina.sln")))
        {
            dir = dir.Parent;
        }
        return dir?.FullName ?? throw new InvalidOperationException("Machina.sln not found above the test folder.");
    }
}

namespace Machina.Tests.Docs;

/// <summary>What README.md and docs/cli.md say of the samples is true (issue 46).</summary>
public class SamplesTextDocTests
{
    [Fact]
    public void CliPage_NamesEveryProgramOfSamplesPrograms_WithTheRightCount()
    {
        string page = string.Join(' ', DocText.ReadLines("docs/cli.md"));
        string[] programs = [.. Directory.EnumerateFiles(DocText.PathOf("samples/programs"), "*.machina").Select(Path.GetFileName).Order(StringComparer.Ordinal)!];
        string[] words = ["none", "one", "two", "three", "four", "five", "six"];

        Assert.Contains($"`samples/programs/` has {words[programs.Length]} programs to try:", page, StringComparison.Ordinal);
        Assert.All(programs, p => Assert.Contains($"`{p}`", page, StringComparison.Ordinal));
    }

    [Fact]
    public void Readme_HelloRobot_IsDescribedOnTheArmTheSampleUses()
    {
        string readme = string.Join(' ', DocText.ReadLines("README.md"));
        string sample = File.ReadAllText(DocText.PathOf("samples/HelloRobot/HelloRobotSample.cs")) + File.ReadAllText(DocText.PathOf("samples/Shared/SampleController.cs"));

        Assert.DoesNotContain("Hello Robot shows on an IRB 120", readme, StringComparison.Ordinal);
        Assert.Contains("Hello Robot runs on the IRB 1200-5/0.9 the samples use, where every one of its actions is executed.", readme, StringComparison.Ordinal);
        Assert.Contains("IRB 1200-5/0.9", sample, StringComparison.Ordinal);
    }
}

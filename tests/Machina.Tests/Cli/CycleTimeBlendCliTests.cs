using System.Globalization;
using System.Text.RegularExpressions;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Tests.Cli;

/// <summary><c>machina check</c>'s cycle time for a UR program with blends, against the time the URScript twin takes to run it compiled.</summary>
public class CycleTimeBlendCliTests
{
    /// <summary>A 100 mm square at 100 mm/s with 20 mm blends at its corners.</summary>
    private const string Program = "SpeedTo(100);\nPrecisionTo(20);\nMoveTo(400, 300, 500);\nMove(100, 0, 0);\nMove(0, -100, 0);\nMove(-100, 0, 0);\nMove(0, 100, 0);\n";

    [Fact]
    public async Task Check_Ur_TimesABlendedSquareAsTheTwinRunsIt()
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", Program);

        CliResult result = await cli.RunAsync("check", "square.machina", "--model", "UR5e");

        Assert.Equal(0, result.Exit);
        Match line = Regex.Match(result.Stdout, @"Estimated cycle time on the [^:]*UR5e: ([0-9.]+) s \(motion ([0-9.]+) s, waits 0\.00 s\); 1 motion not timed");
        Assert.True(line.Success, result.Stdout);
        Assert.DoesNotContain("blends not shortened", result.Stdout, StringComparison.Ordinal);
        double estimate = double.Parse(line.Groups[1].Value, CultureInfo.InvariantCulture);

        var actions = Instructions.Parse(Program);
        RobotModel model = RobotModels.Get("UR5e");
        RobotProgram program = BrandRegistry.For(RobotType.UR).CreateCompiler().Compile(new CompileJob("Square", actions, CompileOptions.Default) { Model = model });
        TwinVerification<UrProgramState> twin = UrScriptVerifier.Verify(program.Files[0].ToText("\n"), actions, new UrTwinOptions { Model = model });

        Assert.True(twin.Passed, twin.ToText());
        Assert.InRange(estimate, twin.Seconds * 0.98, twin.Seconds * 1.02); // one model: well inside the issue's 10 %
        // Without blends the four sides take 4 × (0.1/0.1 + 0.1/1.2) = 4.33 s: three corners passed at speed save about half a second.
        Assert.InRange(estimate, 3.5, 4.33 - 0.3);
    }
}

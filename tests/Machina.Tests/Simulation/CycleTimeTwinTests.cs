using Machina.Simulation.Krl;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation;

/// <summary>
/// The estimated cycle time (<see cref="ProgramTrial.EstimatedDuration"/>, printed by <c>machina check</c> and <c>preview</c>) against
/// the time the brand's twin takes to run the compiled program: within 10 %, the issue's bound, for every reference program.
/// </summary>
public class CycleTimeTwinTests(ITestOutputHelper output)
{
    public static TheoryData<string, RobotType> Programs()
    {
        var data = new TheoryData<string, RobotType>();
        foreach (string name in new[] { "HelloRobot", "SquarePushPop", "Rotations", "JointsToolsIO" })
        {
            foreach (RobotType brand in new[] { RobotType.ABB, RobotType.UR, RobotType.KUKA })
            {
                data.Add(name, brand);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Programs))]
    public void Estimate_IsWithinTenPercentOfTheTwinsTime(string name, RobotType brand)
    {
        // Hello Robot's third move is beyond an IRB 120's reach (RapidGoldenTwinTests): the next size up runs it.
        RobotModel model = RobotModels.Get(brand == RobotType.ABB ? "IRB 1200-5/0.9" : BrandRegistry.For(brand).DefaultModel!);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue(name, brand).GetProgramActions();
        var trial = new ProgramTrial(model);
        foreach (RobotAction action in actions)
        {
            Assert.True(trial.Try(action).Applied, action.ToInstruction());
        }
        RobotProgram program = BrandRegistry.For(brand).CreateCompiler().Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model });

        double twin = TwinSeconds(brand, program, actions, model);

        double estimate = trial.EstimatedDuration.TotalSeconds;
        output.WriteLine($"{name} on the {model}: estimate {estimate:0.000} s, twin {twin:0.000} s, {trial.UntimedMotions} untimed");
        Assert.True(twin > 0.5, $"the twin ran {twin} s");
        Assert.InRange(estimate, twin * 0.9, twin * 1.1);
        Assert.Equal(1, trial.UntimedMotions); // the first motion, from wherever the robot stands (the twin starts there)
    }

    public static TheoryData<RobotType> ZoneBrands() => new() { RobotType.ABB, RobotType.KUKA, RobotType.UR };

    /// <summary>
    /// A zigzag of ten 44.7 mm moves at 500 mm/s (where Hello Robot goes, which every brand's default arm reaches) whose corners have zones of <paramref name="precision"/> mm (ABB z10, KUKA C_DIS
    /// with $APO.CDIS 10, UR r=0.01; 0: fine, exact stops).
    /// </summary>
    private static IReadOnlyList<RobotAction> ZigZag(RobotType brand, double precision)
    {
        Robot bot = Robot.Create("ZigZag", brand);
        bot.SpeedTo(500);
        bot.PrecisionTo(precision);
        bot.MoveTo(300, 300, 500);
        for (int i = 0; i < 10; i++)
        {
            bot.Move(20, i % 2 == 0 ? 40 : -40, 0);
        }
        return bot.GetProgramActions();
    }

    [Theory]
    [MemberData(nameof(ZoneBrands))]
    public void ZigZagWithZones_IsEstimatedWithinTenPercent_AndIsMeasurablyFasterThanWithFine(RobotType brand)
    {
        RobotModel model = RobotModels.Get(brand == RobotType.ABB ? "IRB 1200-5/0.9" : BrandRegistry.For(brand).DefaultModel!);

        (double estimate, double twin) blended = Measure(brand, ZigZag(brand, 10), model);
        (double estimate, double twin) fine = Measure(brand, ZigZag(brand, 0), model);

        output.WriteLine($"{brand} zigzag on the {model}: z10 estimate {blended.estimate:0.000} s, twin {blended.twin:0.000} s; fine estimate {fine.estimate:0.000} s, twin {fine.twin:0.000} s");
        Assert.InRange(blended.estimate, blended.twin * 0.9, blended.twin * 1.1);
        Assert.InRange(fine.estimate, fine.twin * 0.9, fine.twin * 1.1);
        // Nine corners where the arm no longer stops: at 500 mm/s the moves are mostly ramps, and the zones save more than a tenth.
        Assert.InRange(blended.twin, 0.2 * fine.twin, 0.9 * fine.twin);
        Assert.InRange(blended.estimate, 0.2 * fine.estimate, 0.9 * fine.estimate);
    }

    /// <summary>The estimate of <paramref name="actions"/> and the time the brand's twin takes to run them compiled.</summary>
    private static (double Estimate, double Twin) Measure(RobotType brand, IReadOnlyList<RobotAction> actions, RobotModel model)
    {
        var trial = new ProgramTrial(model);
        foreach (RobotAction action in actions)
        {
            Assert.True(trial.Try(action).Applied, action.ToInstruction());
        }
        Assert.Equal(1, trial.UntimedMotions);
        RobotProgram program = BrandRegistry.For(brand).CreateCompiler().Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = model });
        return (trial.EstimatedDuration.TotalSeconds, TwinSeconds(brand, program, actions, model));
    }

    [Fact]
    public void Waits_AddTheirTime_AndJointMovesAreTimedByTheSlowestAxis()
    {
        var trial = new ProgramTrial(RobotModels.Get("KR 6 R900 sixx"));
        Assert.Null(trial.Try(new ActionAxes(new Joints(-90, -90, 90, 0, 0, 0), false)).Duration); // from wherever the robot stands: not timed
        TrialStep wait = trial.Try(new ActionWait(1500));
        TrialStep turn = trial.Try(new ActionAxes(new Joints(90, -90, 90, 0, 0, 0), false));

        Assert.Equal(TimeSpan.FromSeconds(1.5), wait.Duration);
        double rated = RobotModels.Get("KR 6 R900 sixx").MaxJointSpeeds!.Value.J1;
        double ramp = KukaMotionTiming.AxisRampSeconds;
        // A1 travels 180° at its rated speed, ramping up and down in 0.3 s each (a trapezoid when it reaches full speed).
        double expected = 180 / rated + ramp;
        Assert.Equal(expected, turn.Duration!.Value.TotalSeconds, 6);
        Assert.Equal(1.5 + expected, trial.EstimatedDuration.TotalSeconds, 6);
    }

    private static double TwinSeconds(RobotType brand, RobotProgram program, IReadOnlyList<RobotAction> actions, RobotModel model)
    {
        List<(string, string)> Files(params string[] extensions) =>
            [.. program.Files.Where(f => extensions.Contains(f.Extension, StringComparer.OrdinalIgnoreCase)).Select(f => (f.FileName, f.ToText("\n")))];
        switch (brand)
        {
            case RobotType.ABB:
                TwinVerification<RapidProgramState> rapid = RapidVerifier.Verify(Files("mod"), actions, new RapidTwinOptions { Model = model });
                Assert.True(rapid.Passed, rapid.ToText());
                return rapid.Seconds;
            case RobotType.UR:
                TwinVerification<UrProgramState> ur = UrScriptVerifier.Verify(program.Files[0].ToText("\n"), actions, new UrTwinOptions { Model = model });
                Assert.True(ur.Passed, ur.ToText());
                return ur.Seconds;
            default:
                TwinVerification<KrlProgramState> krl = KrlVerifier.Verify(Files("src", "dat"), actions, new KrlTwinOptions { Model = model });
                Assert.True(krl.Passed, krl.ToText());
                return krl.Seconds;
        }
    }
}

// The harness lives in tests/Machina.Benchmarks, which the suite references in its net10.0 build only.
#if NET10_0_OR_GREATER
using Machina.Benchmarks.Differential;
using Machina.Tests.Support;

namespace Machina.Tests.Reliability;

/// <summary>
/// Online equals offline (issue 46), the suite's subset: a program compiled and run on a brand's twin the way <c>machina verify</c>
/// does, and streamed through Machina's driver to the same twin the way <c>machina run --sim</c> does, reach the same poses and
/// joints (0.01 mm, 0.01°), set the same outputs and end the same way, step by step; what the driver cannot stream the pre-check
/// refuses before anything moves. The golden and sample programs, and 30 seeded random programs per brand (the benchmark's
/// <c>--differential</c> runs thousands: docs/reliability.md).
/// </summary>
public class DifferentialPropertyTests
{
    /// <summary>The random programs each brand runs here; the benchmark runs 2,000.</summary>
    private const int RandomPrograms = 30;

    /// <summary>Seeds unlike the benchmark's (which start at 1), so the suite covers other programs.</summary>
    private const int Seed = 46;

    public static TheoryData<string> Brands => new() { "ABB", "UR", "KUKA" };

    public static TheoryData<string, string> Samples()
    {
        var data = new TheoryData<string, string>();
        foreach (string brand in new[] { "ABB", "UR", "KUKA" })
        {
            foreach (string file in Directory.GetFiles(SamplesFolder(), "*.machina").Order(StringComparer.Ordinal))
            {
                data.Add(brand, Path.GetFileName(file));
            }
        }
        return data;
    }

    public static TheoryData<string, string> Golden()
    {
        var data = new TheoryData<string, string>();
        foreach (string brand in new[] { "ABB", "UR", "KUKA" })
        {
            foreach (string name in ReferencePrograms.All.Keys)
            {
                data.Add(brand, name);
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(Samples))]
    public async Task SampleProgram_StreamedOnline_EndsAsItsCompiledProgramEnds(string brand, string file)
    {
        DifferentialCheck.Result result = await DifferentialCheck.RunAsync(Brand(brand), File.ReadAllText(Path.Combine(SamplesFolder(), file)), CancellationToken.None);

        AssertAgree(brand, file, result);
    }

    [Theory]
    [MemberData(nameof(Golden))]
    public async Task GoldenProgram_StreamedOnline_EndsAsItsCompiledProgramEnds(string brand, string name)
    {
        RobotType type = Brand(brand);
        IReadOnlyList<RobotAction> actions = ReferencePrograms.Issue(name, type).GetProgramActions();

        DifferentialCheck.Result result = await DifferentialCheck.RunAsync(type, actions, CancellationToken.None);

        AssertAgree(brand, name, result);
    }

    [Theory]
    [MemberData(nameof(Brands))]
    public async Task RandomPrograms_StreamedOnline_EndAsTheirCompiledProgramsEnd(string brand)
    {
        RobotType type = Brand(brand);
        var verdicts = new List<DifferentialVerdict>();
        for (int i = 0; i < RandomPrograms; i++)
        {
            int seed = DifferentialSuite.SeedOf(Seed, i);
            string program = DifferentialPrograms.Random(type, seed);
            DifferentialCheck.Result result = await DifferentialCheck.RunAsync(type, program, CancellationToken.None);
            AssertAgree(brand, $"seed {seed} (DifferentialPrograms.Random({type}, {seed}))\n{program}", result);
            verdicts.Add(result.Verdict);
        }
        // Most random programs run to their end on both sides: the property is about programs that move.
        Assert.True(verdicts.Count(v => v is DifferentialVerdict.Finished) >= RandomPrograms / 3,
            $"{brand}: {string.Join(", ", verdicts.GroupBy(v => v).Select(g => $"{g.Key} {g.Count()}"))}");
    }

    /// <summary>
    /// The last ABB disagreement of the benchmark (seed 1001871): a relative arc whose CirPoint lies behind its start sweeps a circle
    /// that leaves the IRB 120's reach. The pre-check refuses it before anything moves; the compiled program now stops at that arc
    /// too (the RAPID twin plans the circle, RapidCircle), where before it ran to its end.
    /// </summary>
    [Fact]
    public async Task AbbSeed1001871_ArcLeavingTheReach_BothSidesStop()
    {
        string program = DifferentialPrograms.Random(RobotType.ABB, 1001871);

        DifferentialCheck.Result result = await DifferentialCheck.RunAsync(RobotType.ABB, program, CancellationToken.None);

        Assert.Equal(DifferentialVerdict.Unreachable, result.Verdict);
        Assert.StartsWith("action 5 (ArcMotion(7.5,-10.5,1,-13,17,0);)", result.Detail, StringComparison.Ordinal);
        Assert.Contains("offline: 50050 Position outside reach: ", result.Detail, StringComparison.Ordinal);
        Assert.Empty(result.Online!.Steps);
    }

    /// <summary>The differential check tells a drift apart: a motion 0.02 mm off, or an output set differently, is a disagreement.</summary>
    [Fact]
    public void Compare_ReportsAPoseOffByMoreThanTheTolerance_AndAnOutputThatDiffers()
    {
        IReadOnlyList<RobotAction> actions = Instructions.Parse("MoveTo(300, 0, 400);\nWriteDigital(\"DO_1\", true);\n");
        var pose = new Pose(new Vector(300, 0, 400), Rotation.FlippedAroundY);
        var joints = new Joints(0, 10, 20, 0, 60, 0);
        Machina.Simulation.Twin.TwinTraceEntry Motion(Vector at) => new(3, Machina.Simulation.Twin.TwinTraceKind.Motion, joints, new Pose(at, pose.Rotation), "MoveL", 1);
        Machina.Simulation.Twin.TwinTraceEntry Output(string text) => new(4, Machina.Simulation.Twin.TwinTraceKind.Output, joints, pose, text, 1);
        var offline = new TwinRun(TwinRunEnd.Finished, null, null, [Motion(pose.Position), Output("DO_1 = 1")]);

        DifferentialCheck.Result same = DifferentialCheck.Compare(RobotType.ABB, actions, offline, offline with { Steps = [Motion(new Vector(300, 0.009, 400)), Output("do_1 = 1")] });
        DifferentialCheck.Result moved = DifferentialCheck.Compare(RobotType.ABB, actions, offline, offline with { Steps = [Motion(new Vector(300, 0.02, 400)), Output("DO_1 = 1")] });
        DifferentialCheck.Result output = DifferentialCheck.Compare(RobotType.ABB, actions, offline, offline with { Steps = [Motion(pose.Position), Output("DO_1 = 0")] });

        Assert.Equal(DifferentialVerdict.Finished, same.Verdict);
        Assert.Equal((DifferentialVerdict.Disagreed, "step 1: the TCP is 0.02 mm and 0° apart, the joints up to 0°"), (moved.Verdict, moved.Detail.Split(';')[0]));
        Assert.Equal((DifferentialVerdict.Disagreed, "step 2: the outputs differ"), (output.Verdict, output.Detail.Split(';')[0]));
    }

    private static void AssertAgree(string brand, string what, DifferentialCheck.Result result)
    {
        // Every brand to 0.01 mm and 0.01°: UR's wire carries 0.001 mm and 1e-6 rad since driver 3.0 (docs/protocol-ur.md).
        bool agreed = result.Verdict != DifferentialVerdict.Disagreed;
        Assert.True(agreed, $"{brand} {what}: {result.Verdict}: {result.Detail}");
        if (result.Verdict is DifferentialVerdict.Refused or DifferentialVerdict.Unreachable)
        {
            Assert.Empty(result.Online!.Steps); // the pre-check spoke before anything moved
        }
    }

    private static RobotType Brand(string name) => name switch { "UR" => RobotType.UR, "KUKA" => RobotType.KUKA, _ => RobotType.ABB };

    private static string SamplesFolder() => DifferentialSuite.SamplesFolder() ?? throw new DirectoryNotFoundException("samples/programs");
}
#endif

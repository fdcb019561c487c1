using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Brands.Kuka;

/// <summary>
/// Status and Turn of a compiled Cartesian PTP are those of the pose as written (3 decimals): with the tool pointing down and A4 at
/// about 0°, the rounding can carry A4 to the other side of 0°, and a Turn bit taken from the exact joints names an axis position
/// the controller does not find within the software limit switches (the differential harness' seed 1000009 and ten more).
/// </summary>
public class KrlStatusTurnTests
{
    private static readonly RobotModel Kr6 = RobotModels.Get("KR 6 R900 sixx");

    /// <summary>The first motions of the differential program of seed 1000009 (KUKA), where the compiled PTP stopped.</summary>
    private const string Seed1000009 = """
        SpeedTo(31);
        MotionMode("joint");
        TransformTo(301, -43, 476, -1, 0, 0, 0, 1, 0);
        PushSettings();
        AxesTo(-8.4, -76.15, 128.63, 0, 37.53, -8.4);
        AccelerationTo(2716);
        Move(6, 2, 8);
        Speed(1);
        Move(1.02, -9, -15);
        """;

    [Fact]
    public void CompiledPtp_ToolDown_A4AtZero_RunsOnTheTwin()
    {
        IReadOnlyList<RobotAction> actions = Instructions.Parse(Seed1000009);
        RobotProgram program = Compilers.For(RobotType.KUKA).Compile(new CompileJob("Program", actions, CompileOptions.Default) { Model = Kr6 });
        List<(string, string)> files = [.. program.Files.Select(f => (f.FileName, f.ToText("\n")))];

        TwinVerification<KrlProgramState> result = KrlVerifier.Verify(files, actions, new KrlTwinOptions { Model = Kr6, Limits = TwinLimits.Verify });

        Assert.True(result.Passed, result.ToText() + "\n" + files[0].Item2);
        Assert.Equal(KrlProgramState.Finished, result.State);
    }
}

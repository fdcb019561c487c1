namespace Machina.Tests.Kinematics;

/// <summary>
/// The UR solver's closest solution solves only the branches that could be closest (a lower bound from axes 1 and 5 of each
/// (shoulder, wrist) pair, then axis 3 of each elbow): it must be the solution <see cref="KinematicsCore.ClosestOf"/> picks from all
/// eight raw solutions of the full computation (<see cref="UniversalRobotsSolveBitsTests.FullSolveRaw"/>, the solver as written before),
/// to the last bit, on every UR arm, for references next to the target (a streamed move), anywhere, on the other shoulder's side and
/// the other wrist's, and near the straight wrist, the stretched or folded elbow and axis 1's cylinder; and it must say "out of reach"
/// exactly when there is no raw solution.
/// </summary>
public class UniversalRobotsClosestTests
{
    public static TheoryData<string> UrModels() => UniversalRobotsClosedFormTests.UrModels();

    [Theory]
    [MemberData(nameof(UrModels))]
    public void Closest_IsClosestOfEveryRawSolution_BitForBit(string name)
    {
        RobotModel model = RobotModels.Get(name);
        var kin = (UniversalRobotsKinematics)model.Kinematics;
        var solver = (ISolver)kin;
        var random = new Random(5045);
        Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        int found = 0, unreachable = 0, allEight = 0;
        for (int i = 0; i < 8000; i++)
        {
            Joints j = (i % 7) switch
            {
                0 => Random(random),
                1 => Random(random) with { J5 = Near(random, 0) },                                   // wrist nearly straight
                2 => Random(random) with { J5 = i % 2 == 0 ? 0 : 180 },                              // wrist exactly straight
                3 => Random(random) with { J3 = Near(random, random.Next(2) == 0 ? 0 : 180) },       // elbow stretched or folded
                4 => Within(random),
                5 => Within(random) with { J4 = Near(random, 0), J5 = Near(random, 0) },
                _ => Within(random) with { J5 = Near(random, 90) },
            };
            Pose pose = kin.Forward(j);
            if (i % 50 == 7)
            {
                pose = new Pose(pose.Position * 3, pose.Rotation);                                   // out of reach
            }
            else if (i % 50 == 11)
            {
                pose = new Pose(new Vector(0, 0, pose.Position.Z), pose.Rotation);                   // wrist centre near axis 1
            }
            Affine flange = Affine.FromPose(pose);
            Joints reference = (i % 5) switch
            {
                0 => Nudged(j, random, 0.5),                                                         // the streamed case: just before
                1 => Random(random),
                2 => Nudged(j, random, 0.5) with { J1 = j.J1 + 180 },                                // the other shoulder's side
                3 => Nudged(j, random, 0.5) with { J5 = -j.J5 },                                     // the other wrist
                _ => Nudged(j, random, 1e-9),
            };
            Joints? got = solver.Closest(flange, reference, out bool reachable);
            int n = UniversalRobotsSolveBitsTests.FullSolveRaw(kin.Parameters, flange, reference, raw, configs);
            Joints? want = KinematicsCore.ClosestOf(model, raw[..n], reference);
            Assert.Equal(n > 0, reachable);
            Assert.True(want is null ? got is null : got is Joints g && SameBits.Of(want.Value, g), $"{name}, pose of {j} from {reference}: {got} instead of {want}");
            found += got is null ? 0 : 1;
            unreachable += reachable ? 0 : 1;
            allEight += n == KinematicsCore.MaxSolutions ? 1 : 0;
        }
        Assert.True(found > 7000, $"only {found} solutions: the comparison saw too few");
        Assert.True(unreachable >= 160, $"only {unreachable} unreachable poses");
        Assert.True(allEight > 4000, $"only {allEight} poses had all eight raw solutions");
    }

    [Theory]
    [MemberData(nameof(UrModels))]
    public void Closest_OnAStreamedLine_IsTheFullSearchsSolution(string name)
    {
        // A walk of short lines from known joints (the issue cursor's check and the twin's movel): the public Closest agrees with the
        // full search at every step, including where the walk passes near the straight wrist.
        RobotModel model = RobotModels.Get(name);
        IKinematics kin = model.Kinematics;
        Span<Joints> raw = stackalloc Joints[KinematicsCore.MaxSolutions];
        Span<ArmConfiguration> configs = stackalloc ArmConfiguration[KinematicsCore.MaxSolutions];
        Joints joints = Within(new Random(5046)) with { J5 = 3 };
        Pose start = kin.Forward(joints);
        int steps = 0;
        for (int i = 0; i < 400; i++)
        {
            Pose target = new(start.Position + new Vector(i % 2 == 0 ? 1 : -1, 0.25, -0.5) * (1 + i % 3), start.Rotation);
            Joints? got = kin.Closest(target, joints);
            int n = UniversalRobotsSolveBitsTests.FullSolveRaw(((UniversalRobotsKinematics)kin).Parameters, Affine.FromPose(target), joints, raw, configs);
            Joints? want = KinematicsCore.ClosestOf(model, raw[..n], joints);
            Assert.True(want is null ? got is null : got is Joints g && SameBits.Of(want.Value, g), $"{name}, step {i}: {got} instead of {want}");
            if (got is not Joints next)
            {
                break;
            }
            joints = next;
            start = target;
            steps++;
        }
        Assert.Equal(400, steps);
    }

    private static Joints Random(Random random) => new(Angle(random), Angle(random), Angle(random), Angle(random), Angle(random), Angle(random));

    /// <summary>Joints inside a UR arm's limits (the elbow within ±180°), away from their ends.</summary>
    private static Joints Within(Random random) => new(
        Uniform(random, -170, 170), Uniform(random, -170, 170), Uniform(random, -160, 160),
        Uniform(random, -170, 170), Uniform(random, -170, 170), Uniform(random, -170, 170));

    private static double Uniform(Random random, double min, double max) => min + (max - min) * random.NextDouble();

    private static Joints Nudged(Joints j, Random random, double degrees) => new(
        j.J1 + Step(random, degrees), j.J2 + Step(random, degrees), j.J3 + Step(random, degrees),
        j.J4 + Step(random, degrees), j.J5 + Step(random, degrees), j.J6 + Step(random, degrees));

    private static double Step(Random random, double degrees) => (random.NextDouble() * 2 - 1) * degrees;

    private static double Angle(Random random) => random.NextDouble() * 720 - 360;

    /// <summary>Within a hundredth of a degree of <paramref name="degrees"/>, down to a few ulps of it.</summary>
    private static double Near(Random random, double degrees) => degrees + (random.NextDouble() * 2 - 1) * Math.Pow(10, -random.Next(2, 15));
}

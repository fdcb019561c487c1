namespace Machina.Benchmarks;

/// <summary>
/// Inverse kinematics of one model: every joint solution of one flange pose, with the allocation-free overload. The pose is
/// the forward kinematics of a generic joint configuration, so every solution family exists. A batch of calls is timed; the
/// median batch gives the time per call.
/// </summary>
internal sealed class InverseKinematicsScenario(string name, string model, Joints generic) : Scenario
{
    public override string Name => name;

    public override string Title => $"Inverse kinematics, all solutions of one pose ({model})";

    public override string Unit => "pose";

    public override int TargetSize => 200_000;

    public override IReadOnlyList<int> ScalingSizes => [];

    public override Target Target => Catalog.IkTarget;

    public override Func<object?> Prepare(int size)
    {
        IKinematics kinematics = RobotModels.Get(model).Kinematics;
        Pose pose = kinematics.Forward(generic);
        var solutions = new Joints[8];
        int count = kinematics.Inverse(pose, solutions);
        if (count == 0)
        {
            throw new InvalidOperationException($"The {model} found no solution for its own forward kinematics at {generic}.");
        }
        return () =>
        {
            int found = 0;
            for (int i = 0; i < size; i++)
            {
                found += kinematics.Inverse(pose, solutions);
            }
            return found;
        };
    }
}

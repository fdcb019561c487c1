// Before a program runs: can this arm do it? With a robot model from Machina's catalogue (here an ABB IRB 120, a small
// arm that reaches about 580 mm), every motion is checked the moment it is issued: reach, joint limits, singularities
// (positions where the arm loses a direction and some joints may suddenly spin), posture changes on straight lines, joint
// speeds. This sample issues a short program with two deliberate problems, a target out of reach and a straight line
// that passes where the wrist is straight, and prints, line by line, what the check says, the joints Machina chose, and
// what to change. It is what `machina check program.machina --model "IRB 120"` prints, done with the library.
//
// Usage: dotnet run --project samples/KinematicsCheck [--model "IRB 120"]   (machina models lists the catalogue)
//
// Nothing moves and nothing is written: this is a check you can run while designing.
namespace Machina.Samples;

/// <summary>The kinematics check sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class KinematicsCheckSample
{
    /// <summary>Runs the sample: 0 when the check ran (and, on the IRB 120, found the two planted problems), 1 when it missed them, 2 for wrong arguments.</summary>
    public static Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        string modelName = "IRB 120";
        if (args.Length == 2 && args[0] == "--model")
        {
            modelName = args[1];
        }
        else if (args.Length != 0)
        {
            error.WriteLine("Usage: KinematicsCheck [--model <an ABB model, e.g. \"IRB 120\">]");
            return Task.FromResult(SampleHost.Usage);
        }
        RobotModel? model = RobotModels.Find(modelName);
        if (model is null || model.Brand != RobotType.ABB.ToString())
        {
            error.WriteLine($"\"{modelName}\" is not an ABB model of the catalogue; try \"IRB 120\" or \"IRB 1200-5/0.9\".");
            return Task.FromResult(SampleHost.Usage);
        }

        // The program: each step with what it is for. (A robot created with a model checks every motion when it is issued.)
        var bot = Robot.Create("Check", RobotType.ABB, model);
        var program = new (string Purpose, Action<Robot> Issue)[]
        {
            ("home, tool pointing down", b => b.AxesTo(0, 0, 0, 0, 90, 0)),
            ("speed for the straight lines", b => b.SpeedTo(100)),
            ("above the first corner", b => b.MoveTo(300, -100, 300)),
            ("a straight line 200 mm to the side", b => b.Move(0, 200, 0)),
            ("too far: 620 mm in front of the robot", b => b.MoveTo(620, 0, 300)),
            ("back within reach", b => b.MoveTo(300, 0, 300)),
            ("joint moves until further notice", b => b.MotionMode("joint")),
            ("turn the tool to point forward", b => b.Rotate(0, 1, 0, -90)),
            ("the start of a line across the front", b => b.MoveTo(374, -100, 630)),
            ("straight lines again", b => b.MotionMode("linear")),
            ("a line passing right in front of the robot", b => b.Move(0, 200, 0)),
            ("home again", b => b.AxesTo(0, 0, 0, 0, 90, 0)),
        };

        output.WriteLine($"Checking a program for the {model} (reach, joint limits, singularities, posture changes, joint speeds):");
        output.WriteLine();
        var kinds = new HashSet<KinematicIssueKind>();
        Joints? lineStart = null;
        foreach ((string purpose, Action<Robot> issue) in program)
        {
            cancellationToken.ThrowIfCancellationRequested();
            int before = bot.GetWarnings().Count;
            issue(bot);
            RobotState state = bot.GetIssuedState();
            RobotAction action = state.LastAction!;
            IReadOnlyList<ProgramWarning> found = [.. bot.GetWarnings().Skip(before)];
            output.WriteLine($"#{action.Id,-2} {(found.Count == 0 ? "ok     " : "PROBLEM")} {action.ToInstruction(),-28} // {purpose}");
            if (action is ActionAxes or ActionTranslation or ActionRotation)
            {
                output.WriteLine($"{"",11}joints: {(state.Axes is { } j ? $"{j} ({model.Kinematics.ConfigurationOf(j)})" : "none: the arm cannot get there")}");
            }
            if (purpose.StartsWith("the start of a line", StringComparison.Ordinal))
            {
                lineStart = state.Axes;
            }
            foreach (ProgramWarning warning in found)
            {
                kinds.Add(warning.Kind!.Value);
                output.WriteLine($"{"",11}{warning.Message}");
                output.WriteLine($"{"",11}what to change: {Advice(warning.Kind!.Value, model)}");
            }
        }

        // Every way the arm can reach the start of that line: the line needs the one, its end the other.
        var start = new Pose(new Vector(374, -100, 630), Rotation.FromAxes(new Vector(0, 0, -1), new Vector(0, 1, 0)));
        IReadOnlyList<Joints> solutions = model.Kinematics.Inverse(start);
        output.WriteLine();
        output.WriteLine($"Every way the {model.Name} can put its flange at [374, -100, 630] pointing forward ({solutions.Count} within its joint limits):");
        foreach (Joints solution in solutions)
        {
            string mark = lineStart is { } c && solution.IsSimilar(c, 0.01) ? "  <- the one Machina chose (closest to the joints before)" : "";
            output.WriteLine($"  {solution}  {model.Kinematics.ConfigurationOf(solution)}, RAPID confdata {AbbConfiguration.From(model, solution)}{mark}");
        }

        // Strict mode turns the warnings into refusals: nothing out of reach is ever issued.
        output.WriteLine();
        var strict = Robot.Create("Strict", RobotType.ABB, model);
        strict.StrictMode(true);
        strict.AxesTo(0, 0, 0, 0, 90, 0);
        try
        {
            strict.MoveTo(620, 0, 300);
            output.WriteLine("Strict mode: MoveTo(620,0,300) was accepted.");
        }
        catch (ActionRefusedException ex)
        {
            output.WriteLine($"Strict mode refuses MoveTo(620,0,300): {ex.Reason}");
        }

        output.WriteLine();
        output.WriteLine($"{bot.GetWarnings().Count} warnings in {program.Length} actions; the compiled program carries them too " +
            $"({bot.Compile().Warnings.Count(w => w.Kind is not null)} in RobotProgram.Warnings).");
        // The two problems are planted for the IRB 120; a larger arm may well reach everything.
        if (model.Name == "IRB 120" && (!kinds.Contains(KinematicIssueKind.Unreachable) || !kinds.Contains(KinematicIssueKind.WristSingularity)))
        {
            return Task.FromResult(SampleHost.Fail(error, "the check should have found the unreachable target and the straight wrist; it found " +
                (kinds.Count == 0 ? "nothing" : string.Join(", ", kinds)) + "."));
        }
        return Task.FromResult(SampleHost.Ok);
    }

    /// <summary>What a designer can change for each kind of problem, in plain words.</summary>
    private static string Advice(KinematicIssueKind kind, RobotModel model) => kind switch
    {
        KinematicIssueKind.Unreachable =>
            $"bring the target closer to the robot's base (the {model.Name} cannot reach it), move the workpiece, or choose a larger model.",
        KinematicIssueKind.JointLimit =>
            "turn the tool (or the target) so the joint named stays within its range, or approach from another side.",
        KinematicIssueKind.WristSingularity =>
            "tilt the tool a few degrees (e.g. Rotate(0, 1, 0, 10)) so axis 5 never lines up straight, or make this stretch a joint move (MotionMode(\"joint\")).",
        KinematicIssueKind.ShoulderSingularity =>
            "keep the path away from the space right above the robot's base: go round it.",
        KinematicIssueKind.ElbowSingularity =>
            "do not stretch (or fold) the arm completely: bring the target a little closer (or further).",
        KinematicIssueKind.ConfigurationFlip =>
            "the arm would have to change its posture on a straight line: make this move a joint move, or turn the tool so it need not.",
        KinematicIssueKind.JointSpeed =>
            "slow down (SpeedTo) for this motion.",
        KinematicIssueKind.LargeJointMove =>
            "check that the big swing is intended; an AxesTo before it chooses the way round.",
        _ => "see docs/kinematics.md.",
    };
}

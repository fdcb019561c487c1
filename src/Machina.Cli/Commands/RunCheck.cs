using Machina.Cli.Programs;

namespace Machina.Cli.Commands;

/// <summary>
/// The check <c>machina run</c> makes once connected and before the first action is sent: every statement is read, and every
/// action tried on a copy of the robot's state, as the robot would issue it: what the brand's driver cannot run, what cannot be
/// applied, and (with the arm's model) every target out of reach or beyond a joint's limits stop the run with their line.
/// </summary>
internal static class RunCheck
{
    /// <summary>Most problems listed before the check stops (each one already stops the run).</summary>
    internal const int MaxListed = 20;

    /// <summary>The arm the brand's virtual controller moves like when no model is given (its default settings' model).</summary>
    internal static RobotModel? VirtualModel(RobotType brand) =>
        Machina.Simulation.VirtualControllerRegistry.Has(brand) ? Machina.Simulation.VirtualControllerRegistry.DefaultOptions(brand).Model : null;

    /// <summary>Checks the whole program; returns its number of actions.</summary>
    /// <exception cref="CliException">A statement is malformed, or an action would be refused or cannot be reached; located, nothing sent.</exception>
    internal static long Check(Robot robot, ProgramReader reader, CliContext context)
    {
        ProgramTrial trial = robot.StartTrial();
        long count = 0;
        var problems = new List<string>();
        int more = 0;
        foreach (InstructionStatement statement in reader.Read(context.Cancellation))
        {
            count++;
            TrialStep step = trial.Try(statement.Action);
            string? problem = step.Refusal is string refusal
                ? $"{statement.Action.ToInstruction()} cannot be applied: {refusal}"
                : step.Blocking is KinematicIssue issue
                    ? $"{statement.Action.ToInstruction()} cannot be reached by the {robot.Model?.Name ?? "arm"}: {issue.Reason}"
                    : null;
            if (problem is null)
            {
                continue;
            }
            if (problems.Count < MaxListed)
            {
                problems.Add($"{reader.DisplayName}:{statement.Line}:{statement.Column}: error: {problem}");
            }
            else
            {
                more++;
            }
        }
        if (problems.Count == 0)
        {
            return count;
        }
        if (problems.Count == 1 && more == 0)
        {
            throw new CliException(problems[0] + " Nothing was sent; the robot did not move.") { IsLocated = true };
        }
        string list = string.Join(Environment.NewLine, problems) + (more > 0 ? $"{Environment.NewLine}{reader.DisplayName}: and {more} more." : "");
        throw new CliException($"{list}{Environment.NewLine}{Counted.Of(problems.Count + more, "problem")}: nothing was sent; the robot did not move.") { IsLocated = true };
    }
}

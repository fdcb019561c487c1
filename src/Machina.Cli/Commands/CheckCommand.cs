using System.Globalization;
using Machina.Cli.Programs;

namespace Machina.Cli.Commands;

/// <summary><c>machina check</c>: the pre-flight kinematic checks of a program, line by line.</summary>
internal static class CheckCommand
{
    internal static readonly CliCommand Command = new(
        "check",
        "Check that a robot arm can follow a program, line by line",
        """
        Usage: machina check PROGRAM --model M [--problems-only]

        Follows PROGRAM (a text file of Machina instructions, - for standard input) with the kinematics of the arm model M
        and reports, for every motion, whether the arm can do it: reach, joint limits, wrist/elbow/shoulder singularities,
        configuration flips on straight lines, and joint speeds at the programmed speed. Nothing is written or moved.

        Options:
          --model M          the arm model, e.g. "IRB 120", UR5e, "KR 6 R700 sixx" (machina models lists them)
          --problems-only    report only the motions with a problem

        Example:
          machina check square.machina --model "IRB 120"
        Exit code: 0 when every motion is fine, 1 when some are not (or an instruction is malformed), 2 for a command-line mistake.
        """,
        Options: ["--model"],
        Flags: ["--problems-only"],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (or - for standard input)");
        RobotModel model = Brands.Model(args.Required("--model", "(the arm model, e.g. \"IRB 120\"; machina models lists them)"), null)!;
        bool problemsOnly = args.Has("--problems-only");
        using ProgramReader reader = ProgramReader.Open(path, context, null);
        TextWriter output = context.Stdout;
        await output.WriteLineAsync($"Checking {reader.DisplayName} for the {model.Brand} {model.Name}: reach, joint limits, singularities, " +
            "configuration flips and joint speeds.").ConfigureAwait(false);
        await output.WriteLineAsync().ConfigureAwait(false);
        await output.WriteLineAsync("   LINE:COL RESULT   INSTRUCTION").ConfigureAwait(false);
        var replay = new ProgramReplay(model);
        var problems = new List<string>();
        int motions = 0, withProblems = 0, refused = 0, refusedMotions = 0;
        bool anyProblem = false;
        foreach (ProgramStatement statement in reader.Read(context.Cancellation))
        {
            string? refusal = replay.Apply(statement.Action, problems);
            bool motion = ProgramReplay.IsMotion(statement.Action);
            motions += motion ? 1 : 0;
            string where = string.Create(CultureInfo.InvariantCulture, $"{statement.Line,7}:{statement.Column,-3}");
            if (refusal is not null)
            {
                refused++;
                refusedMotions += motion ? 1 : 0;
                await output.WriteLineAsync($"{where} REFUSED  {statement.Action.ToInstruction()}").ConfigureAwait(false);
                await output.WriteLineAsync($"{"",21}{refusal}").ConfigureAwait(false);
            }
            else if (problems.Count > 0)
            {
                withProblems += motion ? 1 : 0;
                anyProblem = true;
                await output.WriteLineAsync($"{where} PROBLEM  {statement.Action.ToInstruction()}").ConfigureAwait(false);
                foreach (string problem in problems)
                {
                    await output.WriteLineAsync($"{"",21}{problem}").ConfigureAwait(false);
                }
            }
            else if (motion && !problemsOnly)
            {
                await output.WriteLineAsync($"{where} ok       {statement.Action.ToInstruction()}").ConfigureAwait(false);
            }
        }
        await output.WriteLineAsync().ConfigureAwait(false);
        int fine = motions - withProblems - refusedMotions;
        await output.WriteLineAsync($"{motions} motion{(motions == 1 ? "" : "s")} checked: {fine} ok, {withProblems} with problems, {refused} refused" +
            $" (of {replay.Count + refused} actions).").ConfigureAwait(false);
        return refused == 0 && !anyProblem ? ExitCodes.Ok : ExitCodes.Failed;
    }
}

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
        configuration flips on straight lines, and joint speeds at the programmed speed. For a program file it also reports,
        at their lines, the warnings of the model's brand compiler (e.g. a UR blend radius larger than half a motion).
        Nothing is written or moved.

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
        Dictionary<(int Line, int Column), List<string>> brandWarnings = BrandWarnings(reader.FilePath, model, context.Cancellation);
        var trial = new ProgramTrial(model);
        var cycle = new CycleTime();
        var problems = new List<string>();
        int motions = 0, withProblems = 0, refused = 0, refusedMotions = 0;
        bool anyProblem = false;
        foreach (InstructionStatement statement in reader.Read(context.Cancellation))
        {
            TrialStep step = trial.Try(statement.Action);
            cycle.Add(step);
            string? refusal = step.Refusal;
            Problems(step, problems);
            if (refusal is null && brandWarnings.TryGetValue((statement.Line, statement.Column), out List<string>? warnings))
            {
                problems.AddRange(warnings);
            }
            bool motion = step.IsMotion;
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
            $" (of {Counted.Of(trial.AppliedCount + refused, "action")}).").ConfigureAwait(false);
        await output.WriteLineAsync(cycle.ToText($"the {model.Brand} {model.Name}", model)).ConfigureAwait(false);
        return refused == 0 && !anyProblem ? ExitCodes.Ok : ExitCodes.Failed;
    }

    /// <summary>What an applied step deserves a look for, in plain words: its warnings, then the arm's issues (none when refused).</summary>
    internal static void Problems(TrialStep step, List<string> problems)
    {
        problems.Clear();
        if (!step.Applied)
        {
            return;
        }
        problems.AddRange(step.Warnings);
        foreach (KinematicIssue issue in step.Issues)
        {
            problems.Add(issue.ToString());
        }
    }

    /// <summary>
    /// The warnings of the model's brand compiler that are not kinematic (those the replay finds itself), by the line and column of
    /// their statement: the file is compiled into a temporary folder, deleted afterwards. None for standard input, for a model of no
    /// compiled brand, or when the program does not compile (the replay then reports the statement at fault).
    /// </summary>
    private static Dictionary<(int Line, int Column), List<string>> BrandWarnings(string? file, RobotModel model, CancellationToken cancellation)
    {
        var byStatement = new Dictionary<(int Line, int Column), List<string>>();
        if (file is null || BrandRegistry.Find(model.Brand) is not { IsArm: true, Type: RobotType brand })
        {
            return byStatement;
        }
        string folder = Directory.CreateTempSubdirectory("machina-check-").FullName;
        try
        {
            FolderCompileResult result = Instructions.CompileToFolder(file, brand, folder, model: model, cancellationToken: cancellation);
            foreach (ProgramWarning warning in result.Warnings)
            {
                if (warning.Kind is null && warning.Line is int line && warning.Column is int column)
                {
                    if (!byStatement.TryGetValue((line, column), out List<string>? list))
                    {
                        byStatement[(line, column)] = list = [];
                    }
                    list.Add($"{brand}: {warning.Message}");
                }
            }
        }
        catch (InstructionParseException)
        {
            // The replay meets the same statement and reports it.
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
        return byStatement;
    }
}

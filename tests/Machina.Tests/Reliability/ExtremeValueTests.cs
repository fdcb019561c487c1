using System.Reflection;

namespace Machina.Tests.Reliability;

/// <summary>
/// Every verb of <see cref="Robot"/>, every parameter, every edge value of its type (one parameter at a time, and all parameters
/// of a type at once), issued twice from two starting states, then compiled to every language: the verb either issues or
/// refuses with a documented error, and every program compiles to text without NaN, infinities, open strings or broken lines.
/// The million-character texts run in <see cref="HugeTextTests"/>, beside these.
/// </summary>
public class ExtremeValueTests
{
    [Fact]
    public void Verbs_EveryParameterType_HasEdgeValues()
    {
        IReadOnlyList<MethodInfo> verbs = ExtremeValues.Verbs();
        var missing = verbs.SelectMany(m => m.GetParameters())
            .Where(p => ExtremeValues.Edges(p.ParameterType) is null || ExtremeValues.Good(p) is null)
            .Select(p => p.ParameterType.Name).Distinct().ToList();

        Assert.True(missing.Count == 0, "no edge values or no valid value for: " + string.Join(", ", missing));
        Assert.InRange(verbs.Count, 70, 200);
    }

    [Fact]
    public void Verbs_GoodValues_IssueAtLeastOneAction()
    {
        var silent = new List<string>();
        foreach (MethodInfo verb in ExtremeValues.Verbs())
        {
            Robot bot = ExtremeRun.Setups[1].Create();
            try
            {
                verb.Invoke(bot, [.. verb.GetParameters().Select(ExtremeValues.Good)]);
            }
            catch (TargetInvocationException e)
            {
                silent.Add(ExtremeValues.Describe(verb) + ": " + e.InnerException!.Message);
                continue;
            }
            if (bot.GetProgramActions().Count == 0)
            {
                silent.Add(ExtremeValues.Describe(verb));
            }
        }
        Assert.True(silent.Count == 0, "these issue nothing with valid values (add the ones that are no verbs to ExtremeValues.NotVerbs):\n" + string.Join("\n", silent));
    }

    [Fact]
    public async Task Verbs_EdgeValues_IssueOrRefuseClearly_AndEveryLanguageCompilesCleanText()
    {
        ExtremeRun run = await ExtremeRun.RunAsync(huge: false);

        run.AssertNoProblems();
        Assert.InRange(run.Cases, 3_000, 100_000);
        Assert.InRange(run.Issued, run.Cases / 5, run.Cases);
        Assert.InRange(run.Refused, run.Cases / 5, run.Cases);
        Assert.Equal(run.Cases * ExtremeRun.Languages.Length, run.Compiled);
    }
}

/// <summary>Every string parameter of every verb given a million characters, issued once and compiled to every language.</summary>
public class HugeTextTests
{
    [Fact]
    public async Task Verbs_MillionCharacterTexts_IssueOrRefuseClearly_AndEveryLanguageCompilesCleanText()
    {
        ExtremeRun run = await ExtremeRun.RunAsync(huge: true);

        run.AssertNoProblems();
        Assert.InRange(run.Cases, 15, 1_000);
        Assert.InRange(run.Issued, 4, run.Cases);
        // The IO verbs (WriteDigital, WriteAnalog, WaitForDigital) take a pin name of any length: the brands refuse it later.
        Assert.InRange(run.Refused, run.Cases / 3, run.Cases);
        Assert.Equal(run.Cases * ExtremeRun.Languages.Length, run.Compiled);
    }
}

/// <summary>One pass over the verbs and their edge cases, with its counts and the problems found.</summary>
internal sealed class ExtremeRun
{
    internal static readonly RobotType[] Languages = Enum.GetValues<RobotType>();

    /// <summary>Where each case starts: Cartesian pose known (no model), or joints and pose known through a robot model.</summary>
    internal static readonly (string Name, Func<Robot> Create)[] Setups =
    [
        ("pose", () => Prepared(Robot.Create("Edge", RobotType.HUMAN), "TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);")),
        ("model", () => Prepared(Robot.Create("Edge", "ABB", "IRB 120"), "AxesTo(0, 0, 0, 0, 90, 0);")),
    ];

    private readonly List<string> _problems = [];

    internal int Cases { get; private set; }

    internal int Issued { get; private set; }

    internal int Refused { get; private set; }

    internal int Compiled { get; private set; }

    private static Robot Prepared(Robot bot, string start)
    {
        bot.Do("DefineTool(\"T\", 0, 0, 100, 1, 0, 0, 0, 1, 0, 1, 0, 0, 50); ArmAngleTo(10); ExternalAxisTo(1, 10); PushSettings(); PushSettings(); " + start);
        bot.ClearProgram();
        return bot;
    }

    /// <summary>Runs every case without a million-character text (<paramref name="huge"/> false), or only those with one, from the first setup.</summary>
    internal static async Task<ExtremeRun> RunAsync(bool huge)
    {
        var run = new ExtremeRun();
        await Fuzz.RunBoundedAsync(() =>
        {
            foreach (MethodInfo verb in ExtremeValues.Verbs())
            {
                foreach ((string what, object?[] args) in EdgeCases(verb).Where(c => IsHuge(c.Args) == huge))
                {
                    foreach ((string setup, Func<Robot> create) in huge ? Setups[..1] : Setups)
                    {
                        run.Run(create(), verb, args, $"{ExtremeValues.Describe(verb)} with {what}, from {setup}");
                    }
                }
            }
        });
        return run;
    }

    internal void AssertNoProblems() =>
        Assert.True(_problems.Count == 0, $"{_problems.Count} problems in {Cases} cases:\n" + string.Join("\n", _problems.Take(40)));

    private static bool IsHuge(object?[] args) => args.Any(a => a is string { Length: > 1000 } or ActionMessage { Message.Length: > 1000 });

    private void Run(Robot bot, MethodInfo verb, object?[] args, string name)
    {
        Cases++;
        if (Issue(bot, verb, args, name))
        {
            Issued++;
        }
        else
        {
            Refused++;
        }
        CompileEverywhere(bot, name);
    }

    /// <summary>Each parameter at each of its edges (others valid), then every parameter of a type at the same edge.</summary>
    private static IEnumerable<(string What, object?[] Args)> EdgeCases(MethodInfo verb)
    {
        ParameterInfo[] ps = verb.GetParameters();
        object?[] good = [.. ps.Select(ExtremeValues.Good)];
        for (int i = 0; i < ps.Length; i++)
        {
            foreach (object? edge in ExtremeValues.Edges(ps[i].ParameterType)!)
            {
                object?[] args = (object?[])good.Clone();
                args[i] = edge;
                yield return ($"{ps[i].Name} = {Show(edge)}", args);
            }
        }
        foreach (Type type in ps.Select(p => p.ParameterType).Distinct().Where(t => ps.Count(p => p.ParameterType == t) > 1))
        {
            foreach (object? edge in ExtremeValues.Edges(type)!)
            {
                yield return ($"every {type.Name} = {Show(edge)}", [.. ps.Select((p, i) => p.ParameterType == type ? edge : good[i])]);
            }
        }
    }

    private static string Show(object? value) => value switch
    {
        null => "null",
        string s => "\"" + ProgramTextChecks.Shorten(s.Replace("\0", "\\0", StringComparison.Ordinal)) + "\"",
        double d => d.ToString("R", System.Globalization.CultureInfo.InvariantCulture),
        _ => ProgramTextChecks.Shorten(value.ToString() ?? ""),
    };

    /// <summary>
    /// Calls the verb twice (a relative edge value accumulates; a huge text once, to save time); true when issued. Any undocumented
    /// exception is a problem.
    /// </summary>
    private bool Issue(Robot bot, MethodInfo verb, object?[] args, string name)
    {
        int times = IsHuge(args) ? 1 : 2;
        for (int time = 0; time < times; time++)
        {
            try
            {
                verb.Invoke(bot, args);
            }
            catch (TargetInvocationException e) when (e.InnerException is Exception inner)
            {
                if (WhyUnclear(inner, verb) is string why)
                {
                    _problems.Add($"{name}: {why}");
                }
                return false;
            }
        }
        return true;
    }

    /// <summary>Why an exception from a verb is not a clear, documented refusal; null when it is one.</summary>
    private static string? WhyUnclear(Exception e, MethodInfo verb)
    {
        string[] names = [.. verb.GetParameters().Select(p => p.Name!)];
        string? why = e switch
        {
            _ when string.IsNullOrWhiteSpace(e.Message) => "empty message",
            ArgumentException a when !names.Contains(a.ParamName) => $"ParamName \"{a.ParamName}\" is not a parameter of the verb",
            ArgumentException or ActionRefusedException => null,
            InstructionParseException when verb.Name == nameof(Robot.Do) => null,
            _ => "undocumented exception",
        };
        return why is null ? null : $"{why}: {e.GetType().Name}: {ProgramTextChecks.Shorten(e.Message)}";
    }

    /// <summary>Compiles the robot's program to every language (with human comments, where texts are repeated) and checks each text.</summary>
    private void CompileEverywhere(Robot bot, string name)
    {
        foreach (RobotType language in Languages)
        {
            try
            {
                RobotProgram program = bot.Compile(language, new CompileOptions { HumanComments = true });
                if (ProgramTextChecks.Problem(language, program.ToStringList()) is string problem)
                {
                    _problems.Add($"{name}, compiled to {language}: {problem}");
                }
                Compiled++;
            }
            catch (Exception e)
            {
                _problems.Add($"{name}, compiled to {language}: {e.GetType().Name}: {ProgramTextChecks.Shorten(e.Message)}");
            }
        }
    }
}

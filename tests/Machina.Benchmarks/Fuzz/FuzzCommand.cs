using System.Globalization;

namespace Machina.Benchmarks.Fuzz;

/// <summary>
/// <c>--fuzz</c>: the interpreters' fuzz run (issue 40; docs/reliability.md, "Interpreter limits and fuzzing"). Exit code 0 when no
/// case crashed or hung, 1 otherwise.
/// </summary>
internal static class FuzzCommand
{
    public const string Usage = """
        Usage: dotnet run -c Release --project tests/Machina.Benchmarks -- --fuzz [--cases N] [--seed S] [--language ur|rapid|krl] [--save DIR]
          --cases N      cases per language (default 100000)
          --seed S       the random seed (default 1)
          --language L   one language only (repeatable; default all three)
          --save DIR     where the programs of crashes and hangs are written (default fuzz-failures)
        """;

    /// <summary>Runs the fuzz command with its arguments (those after <c>--fuzz</c>).</summary>
    public static int Execute(string[] args)
    {
        int cases = 100_000, seed = 1;
        string save = "fuzz-failures";
        var languages = new List<string>();
        for (int i = 0; i < args.Length; i++)
        {
            switch (args[i])
            {
                case "--cases" when i + 1 < args.Length:
                    cases = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--seed" when i + 1 < args.Length:
                    seed = int.Parse(args[++i], CultureInfo.InvariantCulture);
                    break;
                case "--language" when i + 1 < args.Length:
                    languages.Add(args[++i]);
                    break;
                case "--save" when i + 1 < args.Length:
                    save = args[++i];
                    break;
                default:
                    Console.Error.WriteLine(Usage);
                    return 2;
            }
        }
        bool clean = true;
        foreach (FuzzLanguage language in FuzzLanguage.All(FuzzLanguage.RepositoryRoot()).Where(l => languages.Count == 0 || languages.Contains(l.Name)))
        {
            Console.WriteLine($"Fuzzing {language.Name}: {cases:N0} cases from seed {seed}, {language.Seeds.Count} seed programs");
            FuzzReport report = FuzzRun.Run(language, cases, seed, save, Console.Out);
            Console.WriteLine(report);
            foreach (string crash in report.Crashes.Take(50))
            {
                Console.WriteLine("  CRASH " + crash);
            }
            foreach (string overrun in report.Overruns.Take(50))
            {
                Console.WriteLine("  OVERRUN " + overrun);
            }
            if (report.Hang is not null)
            {
                Console.WriteLine("  HANG " + report.Hang);
            }
            clean &= report.Crashes.Count == 0 && report.Hang is null;
            if (report.Hang is not null)
            {
                break; // the hung case still holds the worker thread
            }
        }
        return clean ? 0 : 1;
    }
}

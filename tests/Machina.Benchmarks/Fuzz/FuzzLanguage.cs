using System.Net;
using System.Text.RegularExpressions;
using Machina.Simulation.Krl;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;
using Machina.Simulation.UrScript;

namespace Machina.Benchmarks.Fuzz;

/// <summary>
/// One interpreter under fuzzing: its seed programs (the golden files of its language, its drivers and a few snippets that
/// loop, recurse and build arrays and strings), the tokens mutations insert, a generator of random programs, and how one case runs
/// (load and run on a fresh twin within the verification's budgets). A case ends as the program's outcome; any other exception
/// escapes, and the fuzz run reports it as a crash.
/// </summary>
internal sealed partial class FuzzLanguage
{
    /// <summary>The step budget of a fuzz case: enough for every seed, small enough that an endless loop costs little.</summary>
    public const long Steps = 20_000;

    private static readonly TwinLimits Limits = TwinLimits.Verify with { MaxSteps = Steps };

    private FuzzLanguage(string name, IReadOnlyList<string> seeds, IReadOnlyList<string> tokens, Func<Random, string> generate, Func<string, CancellationToken, string> run)
    {
        Name = name;
        Seeds = seeds;
        Tokens = tokens;
        Generate = generate;
        Run = run;
    }

    /// <summary>ur, rapid or krl.</summary>
    public string Name { get; }

    /// <summary>The programs mutations start from.</summary>
    public IReadOnlyList<string> Seeds { get; }

    /// <summary>Pieces of the language that mutations insert.</summary>
    public IReadOnlyList<string> Tokens { get; }

    /// <summary>A random program of the language.</summary>
    public Func<Random, string> Generate { get; }

    /// <summary>Runs one case; gives its outcome (refused, failed, finished, stopped).</summary>
    public Func<string, CancellationToken, string> Run { get; }

    /// <summary>The three languages, with seeds read from <paramref name="root"/> (the repository).</summary>
    public static IReadOnlyList<FuzzLanguage> All(string root) => [UrScript(root), Rapid(root), Krl(root)];

    /// <summary>The folder that holds Machina.sln, from the current folder up, else from the running program's folder up.</summary>
    public static string RepositoryRoot()
    {
        foreach (string start in new[] { Environment.CurrentDirectory, AppContext.BaseDirectory })
        {
            for (DirectoryInfo? folder = new(start); folder is not null; folder = folder.Parent)
            {
                if (File.Exists(Path.Combine(folder.FullName, "Machina.sln")))
                {
                    return folder.FullName;
                }
            }
        }
        throw new DirectoryNotFoundException("Machina.sln was not found above the current folder or " + AppContext.BaseDirectory);
    }

    private static List<string> Files(string root, string folder, string pattern) =>
        [.. Directory.GetFiles(Path.Combine(root, folder), pattern).Order(StringComparer.Ordinal).Select(File.ReadAllText)];

    private static FuzzLanguage UrScript(string root)
    {
        List<string> seeds = [.. Files(root, "tests/Machina.Tests/Golden/UR", "*.script"), .. Files(root, "drivers/ur", "*.script"),
            "def p():\n  s = \"ab\"\n  i = 0\n  while i < 30:\n    s = str_cat(s, s)\n    i = i + 1\n  end\nend\n",
            "def p():\n  def f(n):\n    if n > 20:\n      return 0\n    end\n    return f(n + 1) + 1\n  end\n  textmsg(f(0))\nend\n",
            "def p():\n  thread t():\n    sync()\n  end\n  i = 0\n  while i < 10:\n    h = run t()\n    join h\n    i = i + 1\n  end\nend\n",
            "def p():\n  a = [1, 2, 3]\n  a[1] = a[0] * 2\n  x = p[0.1, 0.2, 0.3, 0, 3.14, 0]\n  y = pose_trans(x, x)\n  movel(x, a=1.2, v=0.25)\nend\n"];
        string[] leaves = ["1", "2.5", "x", "True", "\"s\"", "[1, 2]", "p[0, 0, 0, 0, 0, 0]", "sin(0.5)", "str_cat(\"a\", \"b\")", "x[0]", "f(1)"];
        string[] operators = ["+", "-", "*", "/", "%", "==", "!=", "<", ">=", "and", "or"];
        string[] unary = ["-", "not ", "+"];
        string Generate(Random r)
        {
            var lines = new List<string> { "def p():", "  x = 1", "  def f(n):", $"    return {FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary)}", "  end" };
            for (int i = r.Next(1, 8); i > 0; i--)
            {
                string e = FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary);
                lines.Add(r.Next(5) switch
                {
                    0 => $"  while {e}:\n    x = x + 1\n  end",
                    1 => $"  if {e}:\n    x = f(x)\n  else:\n    x = 0\n  end",
                    2 => $"  textmsg({e})",
                    _ => $"  x = {e}",
                });
            }
            lines.Add("end");
            return string.Join('\n', lines) + "\n";
        }
        string Run(string text, CancellationToken token)
        {
            var options = new UrTwinOptions
            {
                Limits = Limits, MaxTrace = 256, SocketOpenTimeout = TimeSpan.FromMilliseconds(50),
                // Every socket of a fuzzed program goes to the discard port of the loopback address, where nothing listens.
                Route = _ => new DnsEndPoint("127.0.0.1", 9),
            };
            using var twin = new UrTwinController(options);
            UrProgramState state = twin.Run(text, token);
            return state == UrProgramState.Finished ? "finished" : Outcome(twin.Error);
        }
        return new("ur", seeds, ["(", ")", "[", "]", "-", "not ", " + 1", "while True:\n", "end\n", "def q():\n", "thread t():\n", "run t()\n",
            "str_cat(s, s)", "f(", "p[", ",", ":", "\n", "  ", "=", "return ", "global ", "1e308", "\"", "#"], Generate, Run);
    }

    private static FuzzLanguage Rapid(string root)
    {
        // The drivers wait for their client without end (WAIT_MAX): a fuzz case gives them 50 ms.
        List<string> seeds = [.. Files(root, "tests/Machina.Tests/Golden/ABB", "*.mod"),
            .. Files(root, "drivers/abb", "*.mod").Select(t => t.Replace("\\Time:=WAIT_MAX", "\\Time:=0.05", StringComparison.Ordinal)),
            "MODULE T\nVAR num a{100};\nVAR string s := \"ab\";\nPROC main()\n  FOR i FROM 1 TO 100 DO\n    a{i} := i * 2;\n  ENDFOR\n  s := s + s;\n  TPWrite s \\Num:=a{3};\nENDPROC\nENDMODULE\n",
            "MODULE T\nFUNC num f(num n)\n  IF n > 20 THEN\n    RETURN 0;\n  ENDIF\n  RETURN f(n + 1) + 1;\nERROR\n  RETURN 0;\nENDFUNC\nPROC main()\n  TPWrite \"\" \\Num:=f(0);\nENDPROC\nENDMODULE\n",
            "MODULE T\nVAR num x := 0;\nPROC main()\n  top:\n  x := x + 1;\n  IF x < 50 GOTO top;\n  WHILE x > 0 DO\n    x := x - 1;\n  ENDWHILE\nENDPROC\nENDMODULE\n"];
        string[] leaves = ["1", "2.5", "x", "TRUE", "\"s\"", "a{1}", "Sin(30)", "f(1)", "x DIV 2", "-x"];
        string[] operators = ["+", "-", "*", "/", "DIV", "MOD", "=", "<>", "<", ">=", "AND", "OR", "XOR"];
        string[] unary = ["-", "NOT ", "+"];
        string Generate(Random r)
        {
            var lines = new List<string> { "MODULE T", "VAR num x := 1;", $"VAR num a{{{r.Next(1, 2000)}}};", "FUNC num f(num n)",
                $"  RETURN {FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary)};", "ENDFUNC", "PROC main()" };
            for (int i = r.Next(1, 8); i > 0; i--)
            {
                string e = FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary);
                lines.Add(r.Next(5) switch
                {
                    0 => $"  WHILE {e} DO\n    x := x + 1;\n  ENDWHILE",
                    1 => $"  IF {e} THEN\n    x := f(x);\n  ELSE\n    x := 0;\n  ENDIF",
                    2 => $"  TPWrite \"\" \\Num:={e};",
                    _ => $"  x := {e};",
                });
            }
            lines.AddRange(["ENDPROC", "ENDMODULE"]);
            return string.Join('\n', lines) + "\n";
        }
        string Run(string text, CancellationToken token)
        {
            var twin = new RapidTwinController(new RapidTwinOptions { Limits = Limits });
            try
            {
                twin.Load(("T.mod", text));
            }
            catch (RapidLoadException)
            {
                return "refused";
            }
            RapidProgramState state = twin.Run("main", token);
            return state == RapidProgramState.Finished ? "finished" : Outcome(twin.Error);
        }
        return new("rapid", seeds, ["(", ")", "[", "]", "{", "}", "-", "NOT ", " + 1", "WHILE TRUE DO\n", "ENDWHILE\n", "PROC q()\n", "ENDPROC\n",
            "f(", ",", ";", ":=", "\n", "VAR num b{46341,46341};\n", "GOTO top;\n", "top:\n", "RETURN ", "\"", "!", "\\Num:=", "RAISE 1;\n"], Generate, Run);
    }

    private static FuzzLanguage Krl(string root)
    {
        List<string> seeds = [.. Files(root, "tests/Machina.Tests/Golden/KUKA", "*.src"), .. Files(root, "drivers/kuka", "*.src"),
            "DEF prog( )\n  DECL INT a[100]\n  DECL INT i\n  FOR i = 1 TO 100\n    a[i] = i * 2\n  ENDFOR\n  $OUT[1] = a[3] > 4\nEND\n",
            "DEF prog( )\n  DECL INT i\n  i = f(0)\nEND\nDEFFCT INT f(n:IN)\n  DECL INT n\n  IF n > 20 THEN\n    RETURN 0\n  ENDIF\n  RETURN f(n + 1) + 1\nENDFCT\n",
            "DEF prog( )\n  DECL INT i\n  i = 0\n  LOOP\n    i = i + 1\n    IF i > 50 THEN\n      EXIT\n    ENDIF\n  ENDLOOP\n  REPEAT\n    i = i - 1\n  UNTIL i < 0\nEND\n"];
        string[] leaves = ["1", "2.5", "x", "TRUE", "a[1]", "SIN(30)", "f(1)", "x * 2", "-x", "$OUT[1]"];
        string[] operators = ["+", "-", "*", "/", "==", "<>", "<", ">=", "AND", "OR", "EXOR", "B_AND"];
        string[] unary = ["-", "NOT ", "+", "B_NOT "];
        string Generate(Random r)
        {
            var lines = new List<string> { "DEF prog( )", "  DECL INT x", $"  DECL INT a[{r.Next(1, 2000)}]", "  x = 1" };
            for (int i = r.Next(1, 8); i > 0; i--)
            {
                string e = FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary);
                lines.Add(r.Next(5) switch
                {
                    0 => $"  WHILE {e}\n    x = x + 1\n  ENDWHILE",
                    1 => $"  IF {e} THEN\n    x = f(x)\n  ELSE\n    x = 0\n  ENDIF",
                    2 => $"  $OUT[2] = {e}",
                    _ => $"  x = {e}",
                });
            }
            lines.AddRange(["END", "DEFFCT INT f(n:IN)", "  DECL INT n", $"  RETURN {FuzzMutator.Expression(r, FuzzMutator.Depth(r), leaves, operators, unary)}", "ENDFCT"]);
            return string.Join('\n', lines) + "\n";
        }
        string Run(string text, CancellationToken token)
        {
            string name = FirstRoutine().Match(text) is { Success: true } m ? m.Groups[1].Value : "prog";
            using var twin = new KrlTwinController(new KrlTwinOptions { Limits = Limits, MaxTrace = 256 });
            try
            {
                twin.Load(token, (name + ".src", text));
            }
            catch (KrlLoadException)
            {
                return "refused";
            }
            KrlProgramState state = twin.Run(cancellation: token);
            return state == KrlProgramState.Finished ? "finished" : Outcome(twin.Error);
        }
        return new("krl", seeds, ["(", ")", "[", "]", "{", "}", "-", "NOT ", " + 1", "WHILE TRUE\n", "ENDWHILE\n", "LOOP\n", "ENDLOOP\n", "DEF q( )\n",
            "END\n", "f(", ",", "=", "\n", "DECL INT b[46341,46341]\n", "CHAR s[2000000000]\n", "RETURN ", "\"", ";", "$OUT[", "#"], Generate, Run);
    }

    /// <summary>The kind of error a failed case ended with (the budget hit, or the program's own error).</summary>
    private static string Outcome(string? error) => error switch
    {
        null => "stopped",
        _ when error.Contains("step budget", StringComparison.Ordinal) => "failed: step budget",
        _ when error.Contains("stack overflow", StringComparison.Ordinal) => "failed: stack",
        _ when error.Contains("nested deeper", StringComparison.Ordinal) || error.Contains("nested calls", StringComparison.Ordinal) => "failed: call depth",
        _ when error.Contains("the twin's limit", StringComparison.Ordinal) => "failed: size limit",
        _ when error.Contains("ompile error", StringComparison.Ordinal) => "refused",
        _ => "failed",
    };

    [GeneratedRegex(@"^\s*(?:GLOBAL\s+)?DEF(?:FCT\s+\w+)?\s+(\w+)\s*\(", RegexOptions.Multiline | RegexOptions.IgnoreCase)]
    private static partial Regex FirstRoutine();
}

using System.Reflection;
using System.Text.RegularExpressions;
using Machina.Tests.Conventions;

namespace Machina.Tests.Samples;

/// <summary>
/// Runs every sample under <c>samples/</c> in-process (each sample project is referenced by this test project through a
/// wildcard, and exposes <c>public static Task&lt;int&gt; RunAsync(string[] args, TextWriter output, TextWriter error,
/// CancellationToken)</c>, which its Program.cs calls too) and checks what it prints. The sample folders are discovered on
/// disk: a new sample gets a row of <see cref="Sample_Run_ExitsZeroAndPrintsWhatItShows"/> at once, which fails until its
/// runs and expected output are added to <see cref="Runs"/>.
/// </summary>
public sealed class SamplesRunTests
{
    /// <summary>How long one sample may take (they take about a second each; this is for a heavily loaded machine).</summary>
    private static readonly TimeSpan Limit = TimeSpan.FromMinutes(2);

    /// <summary>A way the suite runs a sample: its arguments ({out} is a fresh temporary folder) and what its output must hold.</summary>
    private sealed record SampleRun(string Name, string[] Args, Action<string, string> Check);

    /// <summary>Every sample's runs. A sample folder missing here fails <see cref="Sample_Run_ExitsZeroAndPrintsWhatItShows"/>.</summary>
    private static readonly Dictionary<string, SampleRun[]> Runs = new(StringComparer.Ordinal)
    {
        ["HelloRobot"] =
        [
            new("abb", ["--speed-factor", "50"], (output, _) => CheckHelloRobot(output, "ABB IRB 1200-5/0.9 controller", "IRB 1200-5/0.9")),
            new("ur", ["--brand", "ur", "--speed-factor", "50"], (output, _) => CheckHelloRobot(output, "UR UR5e controller", "UR5e")),
            new("kuka", ["--brand", "kuka", "--speed-factor", "50"], (output, _) => CheckHelloRobot(output, "KUKA KR 6 R900 sixx controller", "KR 6 R900 sixx")),
        ],
        ["OfflineCompile"] = [new("all languages", ["{out}"], CheckOfflineCompile)],
        ["ReactiveSquare"] =
        [
            new("two squares", ["--loops", "2", "--speed-factor", "50"], (output, _) =>
            {
                AssertInOrder(output, "Square 1 done, tool at [400, 0, 400]", "Square 2 done, tool at [400, 0, 400]",
                    "Stopped after 2 squares at [400, 0, 400].");
                Assert.DoesNotContain("Square 3", output, StringComparison.Ordinal);
            }),
        ],
        ["PrintGcode"] =
        [
            new("zmorph", ["--out", "{out}"], (output, folder) => CheckPrint(output, folder, "ZMORPH", 5, "G1 X115 Y85 Z0.2 E0.99  ; [Move [30, 0, 0] mm]")),
            new("marlin, 3 layers", ["--printer", "marlin", "--layers", "3", "--out", "{out}"],
                (output, folder) => CheckPrint(output, folder, "MARLIN", 3, "G1 X115 Y85 Z0.2 E0.99 F1500  ; [Move [30, 0, 0] mm]")),
        ],
        ["ToolAndIO"] =
        [
            new("abb", ["--speed-factor", "50"], (output, _) => CheckToolAndIO(output, "ABB", "DO_1", "AO_1")),
            new("ur", ["--brand", "ur", "--speed-factor", "50"], (output, _) => CheckToolAndIO(output, "UR", "1", "1")),
            new("kuka", ["--brand", "kuka", "--speed-factor", "50"], (output, _) => CheckToolAndIO(output, "KUKA", "1", "1")),
        ],
        ["KinematicsCheck"] = [new("IRB 120", [], CheckKinematics)],
        ["BridgeClient"] = [new("embedded bridge", ["--speed-factor", "50"], CheckBridgeClient)],
    };

    /// <summary>Every (sample folder, run) pair; a folder with no runs gives one row that fails.</summary>
    public static TheoryData<string, string> SampleRuns()
    {
        var data = new TheoryData<string, string>();
        foreach (string sample in SampleFolders())
        {
            if (Runs.TryGetValue(sample, out SampleRun[]? runs))
            {
                foreach (SampleRun run in runs)
                {
                    data.Add(sample, run.Name);
                }
            }
            else
            {
                data.Add(sample, "(no runs)");
            }
        }
        return data;
    }

    [Theory]
    [MemberData(nameof(SampleRuns))]
    public async Task Sample_Run_ExitsZeroAndPrintsWhatItShows(string sample, string run)
    {
        SampleRun? sampleRun = Runs.GetValueOrDefault(sample)?.SingleOrDefault(r => r.Name == run);
        Assert.True(sampleRun is not null, $"The sample {sample} is not run by the test suite: add its runs and what it must print to SamplesRunTests.Runs.");

        string folder = Directory.CreateTempSubdirectory("machina-sample-").FullName;
        try
        {
            string[] args = [.. sampleRun.Args.Select(a => a.Replace("{out}", folder, StringComparison.Ordinal))];
            (int exit, string output, string error) = await RunAsync(sample, args);
            Assert.True(exit == 0, $"{sample} {string.Join(' ', args)} exited with {exit}.\n{error}\n{output}");
            Assert.Equal("", error);
            sampleRun.Check(output, folder);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public void SampleFolders_EachIsInTheSolutionWithAReadme_AndEveryRunHasAFolder()
    {
        string root = ConventionTests.RepositoryRoot();
        string solution = File.ReadAllText(Path.Combine(root, "Machina.sln"));
        string readme = File.ReadAllText(Path.Combine(root, "README.md"));
        string[] samples = [.. SampleFolders()];

        Assert.Contains("HelloRobot", samples);
        Assert.Equal(Runs.Keys.Order(StringComparer.Ordinal), samples.Where(Runs.ContainsKey).Order(StringComparer.Ordinal));
        foreach (string sample in samples)
        {
            Assert.Contains($"samples\\{sample}\\{sample}.csproj", solution, StringComparison.Ordinal);
            Assert.True(File.Exists(Path.Combine(root, "samples", sample, "README.md")), $"samples/{sample} has no README.md.");
            Assert.Contains($"samples/{sample}", readme, StringComparison.Ordinal);
        }
    }

    [Fact]
    public async Task Sample_WrongArguments_ExitTwoWithTheirUsage()
    {
        foreach (string sample in SampleFolders())
        {
            (int exit, string output, string error) = await RunAsync(sample, ["--no-such-option", "1", "2"]);
            Assert.True(exit == 2, $"{sample} with a wrong argument exited with {exit}.\n{error}\n{output}");
            Assert.StartsWith("Usage: " + sample, error, StringComparison.Ordinal);
        }
    }

    /// <summary>The folders under samples/ that hold a project of the same name.</summary>
    private static IEnumerable<string> SampleFolders() =>
        Directory.EnumerateDirectories(Path.Combine(ConventionTests.RepositoryRoot(), "samples"))
            .Where(d => File.Exists(Path.Combine(d, Path.GetFileName(d) + ".csproj")))
            .Select(Path.GetFileName).OfType<string>()
            .Order(StringComparer.Ordinal);

    /// <summary>Calls the sample's RunAsync in this process, with its output captured.</summary>
    private static async Task<(int Exit, string Output, string Error)> RunAsync(string sample, string[] args)
    {
        Assembly assembly = Assembly.Load(new AssemblyName(sample));
        MethodInfo entry = assembly.GetExportedTypes()
            .SelectMany(t => t.GetMethods(BindingFlags.Public | BindingFlags.Static))
            .Single(m => m.Name == "RunAsync" && m.ReturnType == typeof(Task<int>)
                && m.GetParameters().Select(p => p.ParameterType).SequenceEqual([typeof(string[]), typeof(TextWriter), typeof(TextWriter), typeof(CancellationToken)]));
        using var output = new StringWriter();
        using var error = new StringWriter();
        // Samples print from the robot's event thread too.
        TextWriter syncOutput = TextWriter.Synchronized(output), syncError = TextWriter.Synchronized(error);
        using var cancellation = new CancellationTokenSource(Limit);
        var run = (Task<int>)entry.Invoke(null, [args, syncOutput, syncError, cancellation.Token])!;
        int exit = await run.WaitAsync(Limit + TimeSpan.FromSeconds(30));
        return (exit, output.ToString().ReplaceLineEndings("\n"), error.ToString().ReplaceLineEndings("\n"));
    }

    private static void CheckHelloRobot(string output, string controller, string model)
    {
        Assert.Contains($"Started a virtual {controller}", output, StringComparison.Ordinal);
        // The sample names no model: the robot learned it from the controller when it connected.
        Assert.Contains($"({model}); the robot is at", output, StringComparison.Ordinal);
        // The seven actions executed in order, each once, the last with nothing left. (How many are left after the others
        // depends on how fast the controller is, compared with issuing.)
        string[] executed = [.. output.Split('\n').Where(l => l.StartsWith("  executed  #", StringComparison.Ordinal))];
        Assert.Equal(7, executed.Length);
        for (int i = 0; i < 7; i++)
        {
            Assert.StartsWith($"  executed  #{i + 1} -> ", executed[i], StringComparison.Ordinal);
        }
        Assert.StartsWith("  executed  #3 -> position [400, 300, 500]", executed[2], StringComparison.Ordinal);
        Assert.StartsWith("  executed  #5 -> position [400, 300, 750]", executed[4], StringComparison.Ordinal);
        // With the controller's arm model, the joint move has a known pose (forward kinematics) and the Cartesian moves known joints.
        Vector flange = RobotModels.Get(model).Kinematics.Forward(new Joints(0, 0, 0, 0, 90, 0)).Position;
        Assert.Equal($"  executed  #7 -> position {flange}, axes [0, 0, 0, 0, 90, 0] (0 left)", executed[6]);
        Assert.All(executed, line => Assert.DoesNotContain("unknown", line, StringComparison.Ordinal));
        string final = Assert.Single(output.Split('\n'), l => l.StartsWith("Done. Final state: ", StringComparison.Ordinal));
        Assert.DoesNotContain("pos null", final, StringComparison.Ordinal);
        Assert.DoesNotContain("rot null", final, StringComparison.Ordinal);
        Assert.DoesNotContain("axes null", final, StringComparison.Ordinal);
        Assert.DoesNotContain("the virtual controller", output, StringComparison.Ordinal);
        // Then the same program offline.
        AssertInOrder(output, "--- ABB: HelloRobot.mod ---", "--- UR: HelloRobot.script ---", "--- KUKA: HelloRobot.src ---", "--- HUMAN: HelloRobot.txt ---");
    }

    private static void CheckOfflineCompile(string output, string folder)
    {
        foreach ((string language, string file) in new[]
        {
            ("ABB", "HelloRobot.mod"), ("UR", "HelloRobot.script"), ("KUKA", "HelloRobot.src"), ("ZMORPH", "HelloRobot.gcode"),
            ("MARLIN", "HelloRobot.gcode"), ("HUMAN", "HelloRobot.txt"), ("MACHINA", "HelloRobot.machina"),
        })
        {
            string path = Path.Combine(folder, language, file);
            Assert.Contains($"{language}: wrote {path}", output, StringComparison.Ordinal);
            Assert.True(File.Exists(path), path);
        }
        Assert.Contains("MoveL [[400, 300, 500]", File.ReadAllText(Path.Combine(folder, "ABB", "HelloRobot.mod")), StringComparison.Ordinal);
        Assert.Contains("MoveTo(400,300,500);", File.ReadAllText(Path.Combine(folder, "MACHINA", "HelloRobot.machina")), StringComparison.Ordinal);
        // A printer cannot rotate its nozzle: the compiler says so.
        Assert.Matches(new Regex(@"ZMORPH: warning #4 Rotate\(0,1,0,-90\); "), output);
    }

    private static void CheckPrint(string output, string folder, string printer, int layers, string firstPrintingLine)
    {
        string path = Path.Combine(folder, "SquareVase.gcode");
        Assert.Contains($"Wrote {path} for a {printer} printer.", output, StringComparison.Ordinal);
        string[] file = File.ReadAllLines(path);
        Assert.Contains($"{file.Length} lines, {layers} layers of 0.2 mm (30 mm square, printed up to Z {0.2 * layers:0.###} mm), {4 * layers} extruding moves.",
            output, StringComparison.Ordinal);
        Assert.Equal($"; Program \"SquareVase\" written by Machina {Robot.Version} for {printer}.", file[0]);
        // The first lines shown: the file's own, down to the first extruding move, after heating the nozzle.
        int first = Array.IndexOf(file, firstPrintingLine);
        Assert.True(first > 0, firstPrintingLine);
        string shown = output[output.IndexOf("First lines:\n", StringComparison.Ordinal)..];
        Assert.Equal(["First lines:", .. file.Take(first + 1).Select(l => "  " + l)], shown.TrimEnd('\n').Split('\n'));
        Assert.Contains("M109 S210  ; [Set Extruder temperature to 210 C and wait]", file);
        Assert.Contains($"G1 X85 Y85 Z{0.2 * layers:0.###} E", file.Single(l => l.Contains($"Z{0.2 * layers:0.###} E", StringComparison.Ordinal)), StringComparison.Ordinal);
    }

    private static void CheckToolAndIO(string output, string brand, string digital, string analog)
    {
        AssertInOrder(output,
            "PERS tooldata gripper := [TRUE,[[0,0,120],[1,0,0,0]],[1.2,[0,0,50],[1,0,0,0],0,0,0]];",
            "SetDO DO_1, 1;", "SetAO AO_1, 0.5;", "WaitTime 0.5;", "SetDO DO_1, 0;",
            "set_tcp(p[0,0,0.12,0,0,0])", "set_payload(1.2, [0,0,0.05])", "set_standard_digital_out(1, True)", "set_standard_analog_out(1, 0.5)",
            "$TOOL = {X 0, Y 0, Z 120, A 0, B 0, C 0}", "$OUT[1] = TRUE", "$ANOUT[1] = 0.5", "WAIT SEC 0.5", "$OUT[1] = FALSE",
            $"Connected to the {brand} controller",
            $"  issued    #5 WriteDigital({(brand == "ABB" ? "\"DO_1\"" : "1")},True);",
            "  executed  #7 (0 left)",
            $"the controller reports: tool tip at [0, 0, 120] from the flange; digital outputs: {digital} = on; analog outputs: {analog} = 0.5.",
            "  executed  #11 (0 left)",
            $"the controller reports: no tool; digital outputs: {digital} = off; analog outputs: {analog} = 0.");
    }

    private static void CheckKinematics(string output, string folder)
    {
        AssertInOrder(output,
            "#4  ok      Move(0,200,0);",
            "#5  PROBLEM MoveTo(620,0,300);",
            "joints: none: the arm cannot get there",
            "Unreachable: the target [620, 0, 300] is out of reach of the ABB IRB 120.",
            "what to change: bring the target closer",
            "#11 PROBLEM Move(0,200,0);",
            "WristSingularity: axis 5 is only 1.9° from straight 45% along the line, at [374, -10, 630]",
            "what to change: tilt the tool",
            "ConfigurationFlip: the arm would have to change configuration",
            "#12 ok      AxesTo(0,0,0,0,90,0);",
            "Every way the IRB 120 can put its flange at [374, -100, 630] pointing forward (3 within its joint limits):",
            "[-18.321, 3.448, -3.541, 89.72, 18.321, -89.705]  shoulder front, elbow up, wrist not flipped, RAPID confdata [-1,0,-1,0]  <- the one Machina chose",
            "Strict mode refuses MoveTo(620,0,300): strict mode: Unreachable: the target [620, 0, 300] is out of reach of the ABB IRB 120.",
            "3 warnings in 12 actions; the compiled program carries them too (3 in RobotProgram.Warnings).");
        Assert.Equal(2, Regex.Count(output, "PROBLEM"));
    }

    private static void CheckBridgeClient(string output, string folder)
    {
        string[] received = [.. output.Split('\n').Where(l => l.StartsWith("<< ", StringComparison.Ordinal)).Select(l => l[3..])];
        string[] hello = ["Message(\\\"Hello Robot!\\\");", "SpeedTo(100);", "MoveTo(400,300,500);", "Rotate(0,1,0,-90);", "Move(0,0,250);", "Wait(2000);", "AxesTo(0,0,0,0,90,0);"];
        foreach (string kind in new[] { "action-issued", "action-released", "action-executed" })
        {
            string[] events = [.. received.Where(e => e.StartsWith($"{{\"event\":\"{kind}\"", StringComparison.Ordinal))];
            Assert.Equal(7, events.Length);
            for (int i = 0; i < 7; i++)
            {
                Assert.StartsWith($"{{\"event\":\"{kind}\",\"last\":\"{hello[i]}\",\"id\":{i + 1},", events[i], StringComparison.Ordinal);
            }
        }
        // Byte for byte as docs/bridge.md shows it (the original's form; the bridge's robot knows its virtual arm, so axes are known).
        Assert.Contains("{\"event\":\"action-executed\",\"last\":\"Move(0,0,250);\",\"id\":5,\"pendDev\":2,\"pendTot\":2,\"pos\":[400,300,750],\"ori\":[0,0,-1,0,1,0],\"quat\":[0.7071,0,0.7071,0],\"axes\":[43.332,-0.672,18.367,-107.858,46.134,114.935],\"extax\":null,\"conf\":null}",
            received);
        Assert.Contains(received, e => e.StartsWith("{\"event\":\"motion-update\",\"pos\":[", StringComparison.Ordinal));
        Assert.Contains("{\"event\":\"error\",\"kind\":\"parse\",\"message\":\"Line 1, column 1: unknown instruction \\\"RotationSpeed\\\".\",\"line\":1,\"column\":1}", received);
        Assert.Contains("Done: 7 actions issued, 7 executed (ids 1, 2, 3, 4, 5, 6, 7).", output, StringComparison.Ordinal);
    }

    /// <summary>Each text appears in <paramref name="output"/>, each after the one before.</summary>
    private static void AssertInOrder(string output, params string[] texts)
    {
        int at = 0;
        foreach (string text in texts)
        {
            int found = output.IndexOf(text, at, StringComparison.Ordinal);
            Assert.True(found >= 0, $"Expected \"{text}\" after position {at} of:\n{output}");
            at = found + text.Length;
        }
    }
}

using System.Diagnostics;

namespace Machina.Benchmarks;

/// <summary>
/// The process under test of the whole-process scenarios: <c>Machina.Benchmarks --child KIND key=value…</c> does what a user's
/// program does (compile an instruction file to a folder, or connect to a controller and stream), once or several times, and
/// prints one JSON line with Stopwatch timestamps (the monotonic clock, comparable between processes on Linux) and its peak
/// resident memory from /proc, so the parent can split process start-up, the work and exit.
/// </summary>
internal static class Child
{
    /// <summary>Runs the child; <paramref name="args"/> start after <c>--child</c>.</summary>
    public static int Run(string[] args, long mainTimestamp)
    {
        Dictionary<string, string> a = args.Skip(1).Select(x => x.Split('=', 2)).ToDictionary(p => p[0], p => p.Length > 1 ? p[1] : "");
        string kind = args.Length > 0 ? args[0] : "";
        int repeat = a.TryGetValue("repeat", out string? r) ? int.Parse(r, System.Globalization.CultureInfo.InvariantCulture) : 1;
        var iterations = new List<double>();
        var iterationCpu = new List<double>();
        var extra = new Dictionary<string, object?>();
        using JitSampler? jit = a.ContainsKey("jitlog") ? new JitSampler() : null;
        using GcEventLog? gcLog = a.ContainsKey("gclog") ? new GcEventLog() : null;
        long workStart = Stopwatch.GetTimestamp();
        for (int i = 0; i < repeat; i++)
        {
            long start = Stopwatch.GetTimestamp();
            double cpuStart = Environment.CpuUsage.TotalTime.TotalSeconds;
            switch (kind)
            {
                case "compile":
                    Compile(a["file"], Enum.Parse<RobotType>(a["brand"]), a["folder"], a.GetValueOrDefault("path", "stream"), extra);
                    break;
                case "stream":
                    Stream(int.Parse(a["port"], System.Globalization.CultureInfo.InvariantCulture), int.Parse(a["count"], System.Globalization.CultureInfo.InvariantCulture), a.GetValueOrDefault("window", "default"), a.GetValueOrDefault("brand", "ABB"), extra);
                    break;
                case "issue-text":
                    IssueText(int.Parse(a["moves"], System.Globalization.CultureInfo.InvariantCulture), a.ContainsKey("sha256"), extra);
                    break;
                case "format-floor":
                    FormatFloor(int.Parse(a["moves"], System.Globalization.CultureInfo.InvariantCulture), extra);
                    break;
                case "write-input":
                    Workloads.WriteInstructionFile(a["file"], int.Parse(a["lines"], System.Globalization.CultureInfo.InvariantCulture));
                    break;
                default:
                    Console.Error.WriteLine($"Unknown child kind \"{kind}\".");
                    return 2;
            }
            iterations.Add(Stopwatch.GetElapsedTime(start).TotalSeconds);
            iterationCpu.Add(Environment.CpuUsage.TotalTime.TotalSeconds - cpuStart);
        }
        long workEnd = Stopwatch.GetTimestamp();
        if (jit is not null)
        {
            extra["jit"] = jit.Samples();
        }
        if (gcLog is not null)
        {
            extra["gc"] = gcLog.Events();
        }
        if (a.ContainsKey("threads"))
        {
            extra["threads"] = ThreadCpu.Read().Values.Select(t => $"{t.Name}:{t.Seconds:0.0000}").ToList();
        }
        extra["gcCollections"] = new[] { GC.CollectionCount(0), GC.CollectionCount(1), GC.CollectionCount(2) };
        extra["allocatedBytes"] = GC.GetTotalAllocatedBytes();
        extra["gcPauseSeconds"] = GC.GetTotalPauseDuration().TotalSeconds;
        (long hwm, long rss) = Memory();
        Console.WriteLine(ChildReport.Write(new Dictionary<string, object?>
        {
            ["main"] = mainTimestamp,
            ["workStart"] = workStart,
            ["workEnd"] = workEnd,
            ["iterations"] = iterations,
            ["iterationCpuSeconds"] = iterationCpu,
            ["peakResidentBytes"] = hwm,
            ["cpuSeconds"] = Environment.CpuUsage.TotalTime.TotalSeconds,
            ["residentBytes"] = rss,
            ["extra"] = extra,
        }));
        return 0;
    }

    /// <summary>
    /// The four ways to compile a file: <c>stream</c>, the library's streaming entry point; <c>tool</c>, the <c>machina compile</c>
    /// command (run by the parent with the tool's own runtime settings); <c>robot-folder</c>, read the whole file, issue it on a
    /// robot and <c>CompileToFolder</c>; <c>robot-memory</c>, the same but <c>Compile()</c> in memory and write each file's
    /// <c>ToText()</c>, as a user who saves a program does.
    /// </summary>
    private static void Compile(string file, RobotType brand, string folder, string path, Dictionary<string, object?> extra)
    {
        switch (path)
        {
            case "stream":
                FolderCompileResult result = Instructions.CompileToFolder(file, brand, folder, programName: "Bench");
                extra["actions"] = result.ActionCount;
                extra["files"] = result.Paths.Count;
                break;
            case "tool":
                var context = new Machina.Cli.CliContext(TextReader.Null, TextWriter.Null, Console.Error, CancellationToken.None);
                int exit = Machina.Cli.CliApp.RunAsync(["compile", file, "--brand", brand.ToString(), "--out", folder, "--name", "Bench"], context).GetAwaiter().GetResult();
                extra["exitCode"] = exit;
                extra["tieredCompilation"] = AppContext.TryGetSwitch("System.Runtime.TieredCompilation", out bool tiered) ? tiered : (bool?)null;
                if (exit != 0)
                {
                    throw new InvalidOperationException($"machina compile ended with exit code {exit}.");
                }
                break;
            case "robot-folder":
            case "robot-memory":
                var bot = Robot.Create("Bench", brand);
                bot.Do(File.ReadAllText(file));
                if (path == "robot-folder")
                {
                    bot.CompileToFolder(folder);
                    break;
                }
                RobotProgram program = bot.Compile();
                Directory.CreateDirectory(folder);
                foreach (RobotProgramFile f in program.Files)
                {
                    File.WriteAllText(Path.Combine(folder, f.FileName), f.ToText(), f.Encoding);
                }
                break;
            default:
                throw new ArgumentException($"Unknown compile path \"{path}\".");
        }
    }

    /// <summary>
    /// Issues <paramref name="moves"/> relative moves on an ABB robot, compiles them in memory and takes every file's text. Each
    /// phase's wall time, processor time, minor page faults, bytes allocated, collections of each generation, the garbage
    /// collector's pause and the methods the JIT compiled on this thread and its time go into <c>phases</c> (issue, compile, text:
    /// seconds, seconds, faults, bytes, gen 0, gen 1, gen 2, seconds, methods, seconds). With <paramref name="sha256"/> (key <c>sha256</c>, not timed by the scenario) also the SHA-256 of the texts
    /// (UTF-16, the files one after the other), so that a change can show it wrote the same text.
    /// </summary>
    private static void IssueText(int moves, bool sha256, Dictionary<string, object?> extra)
    {
        var phases = new Dictionary<string, double[]>();
        long at = Stopwatch.GetTimestamp();
        double cpu = Environment.CpuUsage.TotalTime.TotalSeconds;
        long faults = Machine.MinorPageFaults();
        long allocated = GC.GetAllocatedBytesForCurrentThread();
        int[] collections = [GC.CollectionCount(0), GC.CollectionCount(1), GC.CollectionCount(2)];
        double pause = GC.GetTotalPauseDuration().TotalSeconds;
        static (long, double) MainThreadJit() =>
            (System.Runtime.JitInfo.GetCompiledMethodCount(currentThread: true), System.Runtime.JitInfo.GetCompilationTime(currentThread: true).TotalSeconds);
        (long, double) jit = MainThreadJit();
        void Phase(string name)
        {
            long now = Stopwatch.GetTimestamp();
            double cpuNow = Environment.CpuUsage.TotalTime.TotalSeconds;
            long faultsNow = Machine.MinorPageFaults();
            long allocatedNow = GC.GetAllocatedBytesForCurrentThread();
            int[] collectionsNow = [GC.CollectionCount(0), GC.CollectionCount(1), GC.CollectionCount(2)];
            double pauseNow = GC.GetTotalPauseDuration().TotalSeconds;
            (long, double) jitNow = MainThreadJit();
            phases[name] = [Stopwatch.GetElapsedTime(at, now).TotalSeconds, cpuNow - cpu, faultsNow - faults, allocatedNow - allocated,
                collectionsNow[0] - collections[0], collectionsNow[1] - collections[1], collectionsNow[2] - collections[2], pauseNow - pause,
                jitNow.Item1 - jit.Item1, jitNow.Item2 - jit.Item2];
            (at, cpu, faults, allocated, collections, pause, jit) = (now, cpuNow, faultsNow, allocatedNow, collectionsNow, pauseNow, jitNow);
        }
        Robot? bot = Workloads.IssueToolpath("ABB", moves);
        Phase("issue");
        RobotProgram program = bot.Compile();
        bot = null; // as in a script that compiles once: the robot is not used again
        Phase("compile");
        var texts = new List<string>();
        foreach (RobotProgramFile file in program.Files)
        {
            texts.Add(file.ToText());
        }
        Phase("text");
        extra["phases"] = phases;
        extra["characters"] = texts.Sum(t => (long)t.Length);
        if (!sha256)
        {
            return;
        }
        using var hash = System.Security.Cryptography.IncrementalHash.CreateHash(System.Security.Cryptography.HashAlgorithmName.SHA256);
        foreach (string text in texts)
        {
            hash.AppendData(System.Runtime.InteropServices.MemoryMarshal.AsBytes(text.AsSpan()));
        }
        extra["sha256"] = Convert.ToHexString(hash.GetHashAndReset());
    }

    /// <summary>Formats the three coordinates of <paramref name="moves"/> moves of the benchmark file (same random values) with the shortest round-trip text.</summary>
    private static void FormatFloor(int moves, Dictionary<string, object?> extra)
    {
        var random = new Random(6);
        double[] values = new double[moves * 3];
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = Math.Round((random.NextDouble() - 0.5) * 20, 3);
        }
        Span<char> buffer = stackalloc char[32];
        long characters = 0;
        long start = Stopwatch.GetTimestamp();
        foreach (double value in values)
        {
            value.TryFormat(buffer, out int written, "R", System.Globalization.CultureInfo.InvariantCulture);
            characters += written;
        }
        extra["formatSeconds"] = Stopwatch.GetElapsedTime(start).TotalSeconds;
        extra["characters"] = characters;
    }

    /// <summary>
    /// HelloRobot online: connect, set a speed, move to a start point and stream <paramref name="count"/> relative moves, wait
    /// until all are executed. ABB by default; <c>brand=UR</c> starts where the UR stream of <c>--rtde-rate</c> starts.
    /// </summary>
    private static void Stream(int port, int count, string window, string brand, Dictionary<string, object?> extra)
    {
        var bot = Robot.Create("HelloRobot", brand);
        bot.ControlMode("online");
        if (window == "1")
        {
            bot.BlockSize = 1;
            bot.PendingCount = 1;
        }
        long connect = Stopwatch.GetTimestamp();
        bot.ConnectAsync("127.0.0.1", port).GetAwaiter().GetResult();
        long first = Stopwatch.GetTimestamp();
        bot.SpeedTo(1000);
        if (brand.Equals("UR", StringComparison.OrdinalIgnoreCase))
        {
            bot.MoveTo(300, -300, 400);
        }
        else
        {
            bot.MoveTo(300, 0, 500);
        }
        Vector[] steps = [new(10, 0, 0), new(0, 10, 0), new(-10, 0, 0), new(0, -10, 0)];
        for (int i = 2; i < count; i++)
        {
            bot.Move(steps[i & 3]);
        }
        using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(2) + TimeSpan.FromMilliseconds(count));
        bot.WaitForCompletionAsync(timeout.Token).GetAwaiter().GetResult();
        long done = Stopwatch.GetTimestamp();
        bot.DisconnectAsync().GetAwaiter().GetResult();
        extra["connectTimestamp"] = connect;
        extra["firstIssueTimestamp"] = first;
        extra["doneTimestamp"] = done;
    }

    /// <summary>Peak and current resident memory of this process (VmHWM and VmRSS in /proc/self/status), bytes; 0 when unknown.</summary>
    private static (long Peak, long Current) Memory() =>
        (Machine.StatusBytes("/proc/self/status", "VmHWM:"), Machine.StatusBytes("/proc/self/status", "VmRSS:"));
}

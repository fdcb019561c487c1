// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.Rapid;

/// <summary><c>machina sim abb --load TASK=PATH</c> (issue 42): one RAPID task per name, .sys modules of a folder loaded, PERS shared, lines labelled.</summary>
public class RapidSimTasksCommandTests
{
    [Fact]
    public async Task SimAbbLoad_TwoTasks_ShareAPersFromASystemModule_AndLabelTheirLines()
    {
        using var cli = new CliRunner();
        Directory.CreateDirectory(cli.PathOf("motion"));
        cli.Write("motion/shared.sys", "MODULE shared(SYSMODULE)\n  PERS num stage := 0;\nENDMODULE\n");
        cli.Write("motion/main.mod", "MODULE main_mod\n  PERS num stage;\n  PROC main()\n    WaitUntil stage = 1 \\MaxTime:=20;\n    TPWrite \"motion saw 1\";\n    stage := 2;\n  ENDPROC\nENDMODULE\n");
        cli.Write("helper.mod", "MODULE helper\n  PERS num stage := 0;\n  PROC main()\n    stage := 1;\n    WaitUntil stage = 2 \\MaxTime:=20;\n    TPWrite \"helper saw 2\";\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "T_HELP=helper.mod", "--load", "motion");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.StartsWith("Running 2 RAPID tasks (T_ROB1, T_HELP) on a virtual ABB IRB 120 in real time. Press Ctrl+C to stop.\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  pendant: [T_ROB1] motion saw 1\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  pendant: [T_HELP] helper saw 2\n", result.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("T_ROB1: the program ended.\nT_HELP: the program ended.\n", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimAbbLoad_ASemistaticTask_StartsItsMainAgainWhenItEnds_ANormalOneRunsOnce()
    {
        using var cli = new CliRunner();
        cli.Write("motion.mod", "MODULE motion\n  PROC main()\n    TPWrite \"motion\";\n  ENDPROC\nENDMODULE\n");
        cli.Write("bg.mod", "MODULE bg\n  VAR num runs := 0;\n  PROC main()\n    Incr runs;\n    TPWrite \"cycle \" \\Num:=runs;\n    IF runs = 3 Stop;\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "motion.mod", "--load", "T_BG=bg.mod", "--task-type", "T_BG=SEMISTATIC");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("  pendant: [T_BG] cycle 1\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  pendant: [T_BG] cycle 3\n", result.Stdout, StringComparison.Ordinal);
        Assert.Single(result.Stdout.Split('\n'), l => l == "  pendant: [T_ROB1] motion");
        Assert.EndsWith("T_ROB1: the program ended.\nT_BG: stopped.\n", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimAbbLoad_CycleForever_StartsMainAgainUntilExit()
    {
        using var cli = new CliRunner();
        cli.Write("t.mod", "MODULE t\n  VAR num runs := 0;\n  PROC main()\n    Incr runs;\n    TPWrite \"cycle \" \\Num:=runs;\n    IF runs >= 3 EXIT;\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "t.mod", "--cycle", "forever");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("  pendant: cycle 1\n  pendant: cycle 2\n  pendant: cycle 3\nThe program ended", result.Stdout, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--task-type", "T_BG=FOREVER", "--task-type needs TASK=NORMAL, TASK=STATIC or TASK=SEMISTATIC, e.g. TASK2=SEMISTATIC, not \"T_BG=FOREVER\".")]
    [InlineData("--task-type", "T_X=STATIC", "--task-type T_X: no --load puts a program into the task T_X.")]
    [InlineData("--cycle", "twice", "--cycle needs once or forever, not \"twice\".")]
    public async Task SimAbbLoad_AWrongTaskTypeOrCycle_IsAUsageError(string option, string value, string message)
    {
        using var cli = new CliRunner();
        cli.Write("a.mod", "MODULE a\n  PROC main()\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "a.mod", "--load", "T_BG=a.mod", option, value);

        Assert.Equal(2, result.Exit);
        Assert.Contains(message, result.Stderr, StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("--task-type", "T_BG=STATIC")]
    [InlineData("--cycle", "forever")]
    [InlineData("--signal", "DI_1=1")]
    [InlineData("--eio", "EIO.cfg")]
    public async Task SimAbb_ALoadOnlyOptionWithoutLoad_IsAUsageError_NotIgnored(string option, string value)
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("sim", "abb", "--port", "0", option, value);

        Assert.Equal(2, result.Exit);
        Assert.Contains($"{option} sets up a program that --load runs; without --load it would do nothing. Add --load PROGRAM or leave {option} out.", result.Stderr, StringComparison.Ordinal);
        Assert.Equal("", result.Stdout);
    }

    [Fact]
    public async Task SimAbbLoad_ATaskThatCannotLoad_IsRefusedWithItsTaskModuleLineAndName()
    {
        using var cli = new CliRunner();
        cli.Write("a.mod", "MODULE a\n  PROC main()\n    TPWrite \"a\";\n  ENDPROC\nENDMODULE\n");
        cli.Write("b.mod", "MODULE b\n  PROC main()\n    NoSuchThing 1;\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "a.mod", "--load", "T_B=b.mod");

        Assert.Equal(1, result.Exit);
        Assert.Equal("FAILED: T_B: b.mod: Load error: line 3: Reference error: 'NoSuchThing' is not a procedure (unknown instruction)\n", result.Stdout);
    }

    [Fact]
    public async Task SimAbbLoad_SignalsFromTheCommandLineAndAnEioFile_AreTheProgramsIOConfiguration()
    {
        using var cli = new CliRunner();
        cli.Write("EIO.cfg", "EIO:CFG_1.0:5:60::\n#\nEIO_SIGNAL:\n\n      -Name \"diPart\" -SignalType \"DI\" -Unit \"B\" -UnitMap \"1\"\\\n      -Default \"1\"\n\n"
            + "      -Name \"goRecipe\" -SignalType \"GO\" -Unit \"B\" -UnitMap \"8-15\"\n");
        cli.Write("io.mod", "MODULE io\n  PROC main()\n    TPWrite \"part \" \\Num:=diPart;\n    TPWrite \"estop \" \\Num:=DInput(signalRobotEStop);\n"
            + "    TPWrite \"recipe \" \\Num:=GOutput(goRecipe);\n    TPWrite \"di3 \" \\Num:=DInput(DI_3);\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "io.mod", "--eio", "EIO.cfg", "--signal", "di:signalRobotEStop=1", "--signal", "DI_3=1",
            "--signal", "goRecipe=5", "--rws-port", "0");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("  pendant: part 1\n  pendant: estop 1\n  pendant: recipe 5\n  pendant: di3 1\n", result.Stdout, StringComparison.Ordinal);
        Assert.Matches("\nRobot Web Services \\(RWS 1\\.0\\) on 127\\.0\\.0\\.1:[1-9][0-9]*, user \"Default User\"", result.Stdout);
    }

    [Fact]
    public async Task SimAbbLoad_ASignalNotOnTheBoardWithoutItsType_IsAUsageError()
    {
        using var cli = new CliRunner();
        cli.Write("a.mod", "MODULE a\n  PROC main()\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "a.mod", "--signal", "signalRobotEStop=1");

        Assert.Equal(2, result.Exit);
        Assert.Contains("--signal signalRobotEStop: the board has no such signal; give its type, e.g. --signal di:signalRobotEStop=0.", result.Stderr, StringComparison.Ordinal);
    }
}
#endif

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
    public async Task SimAbbLoad_ATaskThatCannotLoad_IsRefusedWithItsTaskModuleLineAndName()
    {
        using var cli = new CliRunner();
        cli.Write("a.mod", "MODULE a\n  PROC main()\n    TPWrite \"a\";\n  ENDPROC\nENDMODULE\n");
        cli.Write("b.mod", "MODULE b\n  PROC main()\n    NoSuchThing 1;\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "a.mod", "--load", "T_B=b.mod");

        Assert.Equal(1, result.Exit);
        Assert.Equal("FAILED: T_B: b.mod: Load error: line 3: Reference error: 'NoSuchThing' is not a procedure (unknown instruction)\n", result.Stdout);
    }
}
#endif

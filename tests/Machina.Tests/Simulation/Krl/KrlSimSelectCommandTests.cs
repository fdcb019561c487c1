// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// <c>machina sim kuka --load FOLDER --select none|NAME</c>: KUKA's EthernetKRL server for KSS wants the robot interpreter free
/// ($PRO_STATE1 #P_FREE) until its own submit program selects the RSI program with CWRITE's RUN (session 34 found every
/// <c>--load</c> selecting and running the folder's first program, so the server refused its start: "already selected").
/// </summary>
public class KrlSimSelectCommandTests
{
    [Fact]
    public async Task SimKukaLoad_SelectNone_LeavesTheRobotInterpreterFree_AndRunsWhatTheSubmitProgramSelects()
    {
        // The shape of the SDK's ROS_StartProgram: refuse when a program is selected, else RUN it and wait for the state to leave #P_FREE.
        using var cli = new CliRunner();
        Directory.CreateDirectory(Path.Combine(cli.Folder, "cell"));
        cli.Write("cell/aaa_handler.src", """
            DEF aaa_handler( )
            END
            GLOBAL DEF StartRsi( )
              DECL STATE_T st
              DECL MODUS_T mode
              mode = #SYNC
              IF $PRO_STATE1 <> #P_FREE THEN
                MsgNotify("already selected", "SDK", 1)
                RETURN
              ENDIF
              CWRITE($CMD, st, mode, "RUN /R1/rsi_prog()")
              IF st.RET1 == #CMD_OK THEN
                MsgNotify("selected", "SDK", 2)
              ENDIF
            END
            """);
        cli.Write("cell/rsi_prog.src", "DEF rsi_prog( )\n  PTP $AXIS_ACT\n  $OUT[7] = TRUE\nEND\n");
        cli.Write("cell/sps.sub", """
            DEF sps( )
              StartRsi()
              LOOP
                IF $PRO_STATE1 == #P_END THEN
                  MsgNotify("program ended", "SDK", 3)
                  WAIT SEC 3600
                ENDIF
              ENDLOOP
            END
            """);
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(1));
        var stdout = new WatchedWriter();
        Task<CliResult> running = cli.RunAsync(["sim", "kuka", "--load", "cell", "--select", "none"], "", stop.Token, stdout);

        await stdout.WaitForAsync("NOTIFY SDK 3: program ended").WaitAsync(TimeSpan.FromMinutes(1));
        await stop.CancelAsync();
        CliResult result = await running;

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("Loaded aaa_handler.src, rsi_prog.src, sps.sub on a KRL twin of a KUKA KR 6 R900 sixx in real time, no program selected ($PRO_STATE1 #P_FREE)", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  pendant: NOTIFY SDK 2: selected\n", result.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("already selected", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  $OUT[7] = TRUE: TCP", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("OK: the program ran to its end", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimKukaLoad_SelectName_RunsThatProgram_AndAnUnknownNameFails()
    {
        using var cli = new CliRunner();
        Directory.CreateDirectory(Path.Combine(cli.Folder, "cell"));
        cli.Write("cell/aaa.src", "DEF aaa( )\n  $OUT[1] = TRUE\nEND\n");
        cli.Write("cell/bbb.src", "DEF bbb( )\n  $OUT[2] = TRUE\nEND\n");

        CliResult chosen = await cli.RunAsync("sim", "kuka", "--load", "cell", "--select", "bbb");
        CliResult unknown = await cli.RunAsync("sim", "kuka", "--load", "cell", "--select", "ccc");

        Assert.True(chosen.Exit == 0, chosen.Stdout + chosen.Stderr);
        Assert.Contains("Running bbb (aaa.src, bbb.src) on a KRL twin", chosen.Stdout, StringComparison.Ordinal);
        Assert.Contains("  $OUT[2] = TRUE: TCP", chosen.Stdout, StringComparison.Ordinal);
        Assert.DoesNotContain("$OUT[1]", chosen.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, unknown.Exit);
        Assert.Contains("FAILED: --select ccc: no program (a routine without parameters) of that name is loaded\n", unknown.Stdout, StringComparison.Ordinal);
    }
}
#endif

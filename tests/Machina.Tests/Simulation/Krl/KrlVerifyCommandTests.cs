// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.Krl;

public class KrlVerifyCommandTests
{
    [Fact]
    public async Task Verify_Program_RunsItsCompiledKrlOnTheTwin_AndAgreesStepByStep()
    {
        using var cli = new CliRunner();
        cli.Write("square.machina", "SpeedTo(100);\nMoveTo(400, 0, 400);\nMove(50, 0, 0);\nMove(0, 50, 0);\nWriteDigital(2, true);\n");

        CliResult result = await cli.RunAsync("verify", "square.machina", "--brand", "kuka");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.StartsWith("Running the compiled program on a KRL twin of a KUKA KR 6 R900 sixx and comparing it with square.machina.\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains(" ok   Move(50,0,0);\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains(" ok   WriteDigital(2,True);\n", result.Stdout, StringComparison.Ordinal);
        Assert.Matches(@"OK: 4 steps agree; the program runs in [0-9.]+ s\n$", result.Stdout);
    }

    [Fact]
    public async Task Verify_SourceAlone_ListsItsSteps_OrRefusesModWithItsLine()
    {
        using var cli = new CliRunner();
        cli.Write("ok.src", "DEF ok( )\n  PTP {AXIS: A1 0, A2 -90, A3 90, A4 0, A5 90, A6 0}\nEND\n");
        cli.Write("bad.src", "DEF bad( )\n  DECL INT i\n  i = 5 MOD 2\nEND\n");

        CliResult ok = await cli.RunAsync("verify", "ok.src", "--brand", "kuka");
        CliResult bad = await cli.RunAsync("verify", "bad.src", "--brand", "kuka");

        Assert.True(ok.Exit == 0, ok.Stdout + ok.Stderr);
        Assert.Contains("  line 2         0.000 s  PTP (BCO run): TCP", ok.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("OK: the program ran to its end in 0 s\n", ok.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, bad.Exit);
        Assert.Equal("FAILED: bad.src, line 3: KRL has no operator MOD: its arithmetic operators are + - * / (INT division with / truncates)\n", bad.Stdout);
    }

    [Theory]
    [InlineData(new[] { "--signal", "DI_1=1" }, "--signal does nothing when KUKA runs a loaded program (--load); leave it out.")]
    [InlineData(new[] { "--cycle", "forever" }, "--cycle does nothing when KUKA runs a loaded program (--load); leave it out.")]
    [InlineData(new[] { "--rws-port", "0" }, "--rws-port does nothing when KUKA runs a loaded program (--load); leave it out.")]
    [InlineData(new[] { "--port", "7000" }, "--port does nothing when KUKA runs a loaded program (--load); leave it out.")]
    [InlineData(new[] { "--load", "k.src" }, "KUKA --load runs one program (a file or a folder); --load was given 2 times.")]
    public async Task SimKukaLoad_AnOptionTheRunWouldIgnore_IsAUsageError(string[] extra, string message)
    {
        using var cli = new CliRunner();
        cli.Write("k.src", "DEF k( )\nEND\n");

        CliResult result = await cli.RunAsync(["sim", "kuka", "--load", "k.src", .. extra]);

        Assert.Equal(2, result.Exit);
        Assert.Contains(message, result.Stderr, StringComparison.Ordinal);
        Assert.Equal("", result.Stdout);
    }

    [Fact]
    public async Task SimKukaLoad_RunsACompiledProgramOnTheTwin_AndListsItsSteps_OrTheStop()
    {
        using var cli = new CliRunner();
        Directory.CreateDirectory(Path.Combine(cli.Folder, "prog"));
        Directory.CreateDirectory(Path.Combine(cli.Folder, "ok"));
        cli.Write("prog/prog.src", "DEF prog( )\n  PTP $AXIS_ACT\n  $OUT[7] = TRUE\n  PTP {AXIS: A1 175}\nEND\n");
        cli.Write("ok/ok.src", "DEF ok( )\n  PTP $AXIS_ACT\n  $OUT[7] = flag\nEND\n");
        cli.Write("ok/ok.dat", "DEFDAT ok\n  DECL BOOL flag=TRUE\nENDDAT\n");

        CliResult ok = await cli.RunAsync("sim", "kuka", "--load", "ok");
        CliResult stopped = await cli.RunAsync("sim", "kuka", "--load", "prog/prog.src");

        Assert.True(ok.Exit == 0, ok.Stdout + ok.Stderr);
        Assert.StartsWith("Running ok (ok.src, ok.dat) on a KRL twin of a KUKA KR 6 R900 sixx in real time.", ok.Stdout, StringComparison.Ordinal);
        Assert.Contains("  line 3         0.000 s  $OUT[7] = TRUE: TCP", ok.Stdout, StringComparison.Ordinal);
        Assert.EndsWith("OK: the program ran to its end in 0 s\n", ok.Stdout, StringComparison.Ordinal);
        Assert.Equal(1, stopped.Exit);
        Assert.EndsWith("FAILED: Software limit switch A1 +: the target 175 deg is beyond 170 deg (prog.src, line 4)\n", stopped.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimKukaLoad_OfASelectedSource_LoadsTheOtherModulesOfItsFolder_AndNamesItsRsiFiles()
    {
        // As rsi_joint_pos_4ms.src of KUKA's SDK calls ROS_SetAxisCorrLimits of rsi_helper.src beside it.
        using var cli = new CliRunner();
        Directory.CreateDirectory(Path.Combine(cli.Folder, "rsi"));
        cli.Write("rsi/main_prog.src", "DEF main_prog( )\n  PTP $AXIS_ACT\n  SetLimits(2)\nEND\n");
        cli.Write("rsi/helper.src", "DEF helper( )\nEND\nGLOBAL DEF SetLimits(n: IN)\n  INT n\n  $OUT[n] = TRUE\nEND\n");
        cli.Write("rsi/sensor.rsix", "<RsiContext><RsiObjects /></RsiContext>");
        cli.Write("rsi/sensor_ethernet.xml", "<ROOT><CONFIG><IP_NUMBER>127.0.0.1</IP_NUMBER><PORT>59152</PORT></CONFIG></ROOT>");

        CliResult result = await cli.RunAsync("sim", "kuka", "--load", "rsi/main_prog.src");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("RSI file sensor.rsix: read when the program creates its context (RSI_CREATE)\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("RSI file sensor_ethernet.xml: read when the program creates its context (RSI_CREATE)\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("Running main_prog (main_prog.src, helper.src) on a KRL twin", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  $OUT[2] = TRUE: TCP", result.Stdout, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimKukaLoad_RunsTheFoldersSubmitProgram_BesideTheRobotProgram_UntilCtrlC()
    {
        // As KUKA's EKI server for KSS is installed: sps.sub calls the program's routines; the robot program itself may be empty.
        using var cli = new CliRunner();
        Directory.CreateDirectory(Path.Combine(cli.Folder, "cell"));
        cli.Write("cell/cell.src", "DEF cell( )\nEND\nGLOBAL DEF Cell_Init( )\n  MsgNotify(\"server up\", \"CELL\", 1)\nEND\n");
        cli.Write("cell/sps.sub", "DEF sps( )\n  INT turns\n  turns = 0\n  Cell_Init()\n  LOOP\n    turns = turns + 1\n    IF turns == 3 THEN\n      MsgNotify(\"three turns\", \"SPS\", 3)\n    ENDIF\n  ENDLOOP\nEND\n");
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(1));
        var stdout = new WatchedWriter();
        Task<CliResult> running = cli.RunAsync(["sim", "kuka", "--load", "cell"], "", stop.Token, stdout);

        await stdout.WaitForAsync("NOTIFY SPS 3: three turns").WaitAsync(TimeSpan.FromMinutes(1));
        await stop.CancelAsync();
        CliResult result = await running;

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains("Running cell (cell.src, sps.sub) on a KRL twin", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("Submit interpreter: sps.sub (sps) runs beside the robot program, one turn of its LOOP per 12 ms cycle\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("  pendant: NOTIFY CELL 1: server up\n", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("OK: the program ran to its end", result.Stdout, StringComparison.Ordinal);
        Assert.Contains("The submit interpreter runs on until Ctrl+C.\n", result.Stdout, StringComparison.Ordinal);
    }
}
#endif

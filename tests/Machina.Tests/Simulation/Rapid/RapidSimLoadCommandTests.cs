// The command-line tool is .NET 10 only (see Machina.Tests.csproj): these tests run with the net10.0 build.
#if NET10_0_OR_GREATER
using System.Globalization;
using System.Net;
using System.Text;
using System.Text.RegularExpressions;
using Machina.Tests.Cli;

namespace Machina.Tests.Simulation.Rapid;

public class RapidSimLoadCommandTests
{
    [Fact]
    public async Task SimAbbLoad_RunsMainInRealTime_TellsThePendant_AndTheEnd()
    {
        using var cli = new CliRunner();
        cli.Write("hello.mod", "MODULE hello\nPROC main()\n  TPWrite \"hello\";\n  MoveAbsJ [[0, 0, 0, 0, 80, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0 \\T:=0.05;\n  TPWrite \"there\";\nENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "hello.mod");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Equal(
            "Running hello.mod on a virtual ABB IRB 120 (RAPID, task T_ROB1) in real time. Press Ctrl+C to stop.\n  pendant: hello\n  pendant: there\n"
            + "The program ended after 0.05 s of program time.\n",
            result.Stdout);
    }

    [Fact]
    public async Task SimAbbLoad_UnknownInstruction_RefusedWithItsLine_UnreachableMove_FailsWithTheEvent()
    {
        using var cli = new CliRunner();
        cli.Write("bad.mod", "MODULE bad\nPROC main()\n  MoveLL p10, v100, z5, tool0;\nENDPROC\nENDMODULE\n");
        cli.Write("far.mod", "MODULE far\nPROC main()\n  MoveL [[3000, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;\nENDPROC\nENDMODULE\n");

        CliResult bad = await cli.RunAsync("sim", "abb", "--load", "bad.mod");
        CliResult far = await cli.RunAsync("sim", "abb", "--load", "far.mod");
        CliResult ur = await cli.RunAsync("sim", "ur", "--load", "far.mod");

        Assert.Equal(1, bad.Exit);
        Assert.Equal("FAILED: bad.mod: Load error: line 3: Reference error: 'MoveLL' is not a procedure (unknown instruction)\n", bad.Stdout);
        Assert.Equal(1, far.Exit);
        Assert.Matches(@"\nFAILED: 50050 Position outside reach: .* \(line 3, task T_ROB1\)\n$", far.Stdout);
        Assert.Equal(2, ur.Exit);
        Assert.Contains("--load runs compiled programs on abb (RAPID) and kuka (KRL), not on ur.", ur.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimAbbLoad_Home_IsTheFolderTheProgramsFilesGoTo()
    {
        using var cli = new CliRunner();
        Directory.CreateDirectory(cli.PathOf("cell"));
        cli.Write("cell/recipe.txt", "glue 3\n");
        cli.Write("log.mod", "MODULE log\n  VAR iodev f;\n  VAR string r;\n  PROC main()\n    Open \"HOME:/recipe.txt\", f \\Read;\n    r := ReadStr(f);\n"
            + "    Close f;\n    Open \"HOME:/logs.txt\", f \\Write;\n    Write f, \"ran \" + r;\n    Close f;\n  ENDPROC\nENDMODULE\n");

        CliResult result = await cli.RunAsync("sim", "abb", "--load", "log.mod", "--home", "cell");
        CliResult ur = await cli.RunAsync("sim", "ur", "--home", "cell");

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Contains($"RAPID's HOME: is the folder {cli.PathOf("cell")}.\n", result.Stdout, StringComparison.Ordinal);
        Assert.Equal("ran glue 3\n", File.ReadAllText(cli.PathOf("cell/logs.txt")));
        Assert.Equal(2, ur.Exit);
        Assert.Contains("--home is the mass memory of a virtual ABB (RAPID's HOME:), not of ur.", ur.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task SimAbb_HomeWithoutLoad_IsWhatRwsFileServiceWritesTo_AndIsKeptAfterTheStop()
    {
        using var cli = new CliRunner();
        using var cancel = new CancellationTokenSource();
        var stdout = new WatchedWriter();
        Task<CliResult> sim = cli.RunAsync(["sim", "abb", "--port", "0", "--rws-port", "0", "--home", "cell"], "", cancel.Token, stdout);
        try
        {
            await stdout.WaitForAsync("RAPID's HOME:, the folder ");
            Match rws = Regex.Match(stdout.Text, @"Robot Web Services \(RWS 1\.0\) on 127\.0\.0\.1:([0-9]+),");
            Assert.True(rws.Success, stdout.Text);
            Assert.Contains($"RWS's /fileservice/$HOME is RAPID's HOME:, the folder {cli.PathOf("cell")}.\n", stdout.Text, StringComparison.Ordinal);
            using var http = Machina.Tests.Rws.RwsTestClient.For(int.Parse(rws.Groups[1].Value, CultureInfo.InvariantCulture), new CookieContainer(), TimeSpan.FromSeconds(30));
            using HttpResponseMessage put = await http.PutAsync("/fileservice/$HOME/from-rws.txt", new StringContent("uploaded\n", Encoding.ASCII));
            Assert.True(put.IsSuccessStatusCode, put.ToString());
        }
        finally
        {
            await cancel.CancelAsync();
        }
        CliResult result = await sim;

        Assert.True(result.Exit == 0, result.Stdout + result.Stderr);
        Assert.Equal("uploaded\n", File.ReadAllText(cli.PathOf("cell/from-rws.txt")));
    }
}
#endif

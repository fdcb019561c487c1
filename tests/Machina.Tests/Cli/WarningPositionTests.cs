namespace Machina.Tests.Cli;

/// <summary>
/// Every warning carries its statement's line and column, in every command, including a UR blend warning about a motion that
/// only the next motion shows to be too short for its blend radius; the warning is in the .script too, and check reports it.
/// </summary>
public sealed class WarningPositionTests
{
    private const string Blend = """
        PrecisionTo(5);
        TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);
        Move(40, 0, 0);
          Move(8, 0, 0);
        """;

    private const string NextText =
        "the blend radius of 5 mm is more than half of the next motion (8 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(4) or less around short motions.";

    private const string ThisText =
        "the blend radius of 5 mm is more than half of this motion (8 mm long); blends cannot overlap: a UR controller logs a warning and runs on (the twin blends with half of the motion). Use PrecisionTo(4) or less around short motions.";

    [Fact]
    public void CompileToFolder_BlendWarningAboutThePreviousMotion_CarriesThatMotionsLine()
    {
        string folder = Directory.CreateTempSubdirectory("machina-warn-").FullName;
        try
        {
            FolderCompileResult result = Instructions.CompileToFolder(new StringReader(Blend), RobotType.UR, folder, programName: "blend");

            Assert.Equal(
                [(3, 1, "Move(40,0,0);", NextText), (4, 3, "Move(8,0,0);", ThisText)],
                result.Warnings.Select(w => (w.Line ?? 0, w.Column ?? 0, w.Instruction, w.Message)));
            string script = File.ReadAllText(Assert.Single(result.Paths));
            Assert.Contains("  # WARNING: Move(40,0,0); " + NextText, script, StringComparison.Ordinal);
            Assert.Contains("  # WARNING: Move(8,0,0); " + ThisText, script, StringComparison.Ordinal);
        }
        finally
        {
            Directory.Delete(folder, recursive: true);
        }
    }

    [Fact]
    public async Task Compile_Ur_BlendWarningsPointAtTheirStatements()
    {
        using var cli = new CliRunner();
        cli.Write("blend.machina", Blend);

        CliResult result = await cli.RunAsync("compile", "blend.machina", "--brand", "ur", "--out", "out");

        Assert.Equal(0, result.Exit);
        Assert.Equal(
            [
                "blend.machina:3:1: warning: Move(40,0,0); " + NextText,
                "blend.machina:4:3: warning: Move(8,0,0); " + ThisText,
            ],
            result.Stderr.Split('\n').Where(l => l.Contains(": warning: ", StringComparison.Ordinal)));
    }

    [Fact]
    public async Task Check_Ur5e_ReportsTheBlendWarningsAtTheirLines()
    {
        using var cli = new CliRunner();
        cli.Write("blend.machina", Blend);

        CliResult result = await cli.RunAsync("check", "blend.machina", "--model", "UR5e");

        Assert.Equal(1, result.Exit);
        string[] lines = result.Stdout.Split('\n').Select(l => l.TrimEnd('\r')).ToArray();
        int move40 = Array.FindIndex(lines, l => l.Contains("Move(40,0,0);", StringComparison.Ordinal));
        int move8 = Array.FindIndex(lines, l => l.Contains("Move(8,0,0);", StringComparison.Ordinal));
        Assert.Equal("      3:1   PROBLEM  Move(40,0,0);", lines[move40]);
        Assert.Equal("      4:3   PROBLEM  Move(8,0,0);", lines[move8]);
        int next = Array.IndexOf(lines, $"{"",21}UR: {NextText}");
        int self = Array.IndexOf(lines, $"{"",21}UR: {ThisText}");
        Assert.True(move40 < next && next < move8 && move8 < self, $"The UR warnings are not under their statements:\n{result.Stdout}");
        Assert.DoesNotContain(lines, l => l.Contains(" ok ", StringComparison.Ordinal) && l.Contains("Move(", StringComparison.Ordinal));
    }
}

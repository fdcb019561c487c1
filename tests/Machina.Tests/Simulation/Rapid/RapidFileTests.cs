using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// File I/O on the controller's mass memory (Open, Write, Close, ReadStr, ReadNum, IsFile, MakeDir, RemoveFile), as cycle-time loggers
/// use it: the files live in the twin's sandbox directory (HOME:), and a name that leads out of it raises ERR_FILEOPEN.
/// </summary>
public sealed class RapidFileTests : IDisposable
{
    private readonly DirectoryInfo _root = Directory.CreateTempSubdirectory("machina-rapid-file-tests-");

    private string Home => Path.Combine(_root.FullName, "home");

    public void Dispose() => _root.Delete(recursive: true);

    private RapidTwinController Run(string body)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { HomeDirectory = Home });
        twin.Load(("T.mod", $"MODULE T\n  VAR iodev log;\n  VAR num n;\n  PROC main()\n{body}\n  ERROR\n    TPWrite \"error \" + ValToStr(ERRNO = ERR_FILEOPEN) + \" \" + ValToStr(ERRNO = ERR_FILEACC);\n    TRYNEXT;\n  ENDPROC\nENDMODULE\n"));
        RapidProgramState state = twin.Run();
        Assert.True(state == RapidProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    [Fact]
    public void ALogWrittenAppendedAndReadBack_IsAFileOfTheSandbox()
    {
        RapidTwinController twin = Run(
            """
                Open "HOME:/logs/cycle.txt", log \Write;
                MakeDir "HOME:/logs";
                Open "HOME:" \File:="logs/cycle.txt", log \Write;
                Write log, "cycle " \Num:=12.5;
                Write log, "ok " \Bool:=TRUE;
                Write log, "3.25";
                Close log;
                Open diskhome \File:="logs/cycle.txt", log \Append;
                Write log, "appended" \NoNewLine;
                Close log;
                Open "home:/logs/cycle.txt", log \Read;
                TPWrite ReadStr(log);
                TPWrite ReadStr(log);
                n := ReadNum(log);
                TPWrite "twice " \Num:=2 * n;
                TPWrite ReadStr(log);
                TPWrite ReadStr(log);
                TPWrite "EOF_NUM " \Bool:=ReadNum(log) = EOF_NUM;
                Write log, "no";
                Close log;
                TPWrite "file " \Bool:=IsFile("HOME:/logs/cycle.txt");
                TPWrite "folder " \Bool:=IsFile("HOME:/logs" \Directory);
            """);

        // The first Open fails: the folder is not there yet (ERR_FILEOPEN); a Write to a file opened for reading is ERR_FILEACC.
        Assert.Equal(
            ["error TRUE FALSE", "cycle 12.5", "ok TRUE", "twice 6.5", "appended", "EOF", "EOF_NUM TRUE", "error FALSE TRUE", "file TRUE", "folder TRUE"],
            twin.Pendant.Lines);
        Assert.Equal("cycle 12.5\nok TRUE\n3.25\nappended", File.ReadAllText(Path.Combine(Home, "logs", "cycle.txt")));
        Assert.Equal(Home, twin.HomeDirectory);
    }

    [Fact]
    public void NamesOutsideTheSandbox_OrOfAMissingFile_RaiseErrFileopen_AndNothingIsWrittenOutside()
    {
        RapidTwinController twin = Run(
            """
                Open "HOME:/../escape.txt", log \Write;
                Open "HOME:/a/../../escape.txt", log \Write;
                Open "/hd0a/escape.txt", log \Write;
                Open "C:/escape.txt", log \Write;
                Open "HOME:/missing.txt", log \Read;
                RemoveFile "HOME:/missing.txt";
                Open "TEMP:/t.txt", log;
                Write log, "temp";
                Close log;
                TPWrite "temp " \Bool:=IsFile("TEMP:/t.txt");
                RemoveFile "TEMP:/t.txt";
                TPWrite "removed " \Bool:=NOT IsFile("TEMP:/t.txt");
            """);

        Assert.Equal(
            ["error TRUE FALSE", "error TRUE FALSE", "error TRUE FALSE", "error TRUE FALSE", "error TRUE FALSE", "error FALSE TRUE", "temp TRUE", "removed TRUE"],
            twin.Pendant.Lines);
        Assert.False(File.Exists(Path.Combine(_root.FullName, "escape.txt")));
        Assert.Empty(Directory.GetFiles(_root.FullName));
    }
}

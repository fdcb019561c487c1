using System.Diagnostics;
using System.Text;
using Machina.Simulation.Rapid;
using Xunit.Abstractions;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>The RAPID twin's loader refuses what a controller refuses (with the line), and runs RAPID's statements as the manual says.</summary>
public class RapidLanguageTests(ITestOutputHelper output)
{
    private static RapidTwinController Run(string body, string data = "", RapidProgramState expected = RapidProgramState.Finished, RapidTwinOptions? options = null)
    {
        var twin = new RapidTwinController(options);
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        Assert.Equal(expected, twin.Run());
        return twin;
    }

    private static RapidLoadException Refused(string module) =>
        Assert.Throws<RapidLoadException>(() => new RapidTwinController().Load(("T.mod", module)));

    [Fact]
    public void UnknownInstruction_IsRefusedWithItsLine()
    {
        RapidLoadException ex = Refused("MODULE T\nPROC main()\n  TPWrite \"a\";\n  MoveX p10, v100;\nENDPROC\nENDMODULE");

        Assert.Equal(4, ex.Line);
        Assert.Equal("Load error: line 4: Reference error: 'MoveX' is not a procedure (unknown instruction)", ex.Message);
    }

    [Theory]
    [InlineData("VAR num a := \"text\";", 3, "Type error: type mismatch: expected num, found string")]
    [InlineData("VAR robtarget p := [[1,2,3],[1,0,0,0]];", 3, "Type error: a robtarget has 4 components, the aggregate has 2")]
    [InlineData("VAR pos p; VAR num x := p.w;", 3, "Reference error: 'w' is not a component of pos")]
    [InlineData("CONST num k := 1;", 5, "Reference error: 'k' is a constant and cannot be assigned")]
    [InlineData("VAR num a := undefinedName;", 3, "Reference error: 'undefinedName' is unknown (not data)")]
    public void TypeAndNameErrors_AreRefusedWithTheirLine(string declaration, int line, string reason)
    {
        RapidLoadException ex = Refused($"MODULE T\n\n{declaration}\nPROC main()\n  k := 2;\nENDPROC\nENDMODULE");

        Assert.Equal(line, ex.Line);
        Assert.Equal(reason, ex.Reason);
    }

    [Fact]
    public void SyntaxError_IsRefusedWithItsLine()
    {
        RapidLoadException ex = Refused("MODULE T\nPROC main()\n  IF TRUE THEN\n    TPWrite \"a\";\nENDPROC\nENDMODULE");

        Assert.Equal(5, ex.Line);
        Assert.Equal("Syntax error: 'ENDIF' expected, found 'ENDPROC'", ex.Reason);
    }

    [Fact]
    public void ControlFlow_IfWhileForTestGoto_RunAsTheManualSays()
    {
        RapidTwinController twin = Run("""
              VAR num sum := 0;
              VAR num n := 0;
              FOR i FROM 1 TO 10 DO
                sum := sum + i;
              ENDFOR
              FOR i FROM 10 TO 1 STEP -3 DO
                TPWrite "down " \Num:=i;
              ENDFOR
              WHILE n < 3 DO
                n := n + 1;
              ENDWHILE
              TEST n
              CASE 1, 2:
                TPWrite "small";
              CASE 3:
                TPWrite "three";
              DEFAULT:
                TPWrite "other";
              ENDTEST
              IF sum = 55 TPWrite "sum " \Num:=sum;
              IF n > 5 THEN
                TPWrite "no";
              ELSEIF n = 3 AND NOT sum <> 55 THEN
                TPWrite "elseif";
              ELSE
                TPWrite "no";
              ENDIF
              again:
              n := n - 1;
              IF n > 0 GOTO again;
              TPWrite "n " \Num:=n;
              TPWrite "div " \Num:=17 DIV 5;
              TPWrite "mod " \Num:=17 MOD 5;
            """);

        Assert.Equal(["down 10", "down 7", "down 4", "down 1", "three", "sum 55", "elseif", "n 0", "div 3", "mod 2"], twin.Pendant.Lines);
    }

    [Fact]
    public void FunctionsRecordsArraysAndReferenceParameters_Work()
    {
        RapidTwinController twin = Run(
            """
              VAR num values{3} := [1, 2, 3];
              VAR robtarget p := [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              Twice values{2};
              p.trans.x := Square(4);
              TPWrite ValToStr(values);
              TPWrite ValToStr(p.trans);
              TPWrite "opt " \Bool:=HasOpt(\X:=1);
              TPWrite "opt " \Bool:=HasOpt();
            """,
            """
            FUNC num Square(num x)
              RETURN x * x;
            ENDFUNC
            PROC Twice(INOUT num x)
              x := 2 * x;
            ENDPROC
            FUNC bool HasOpt(\num X)
              RETURN Present(X);
            ENDFUNC
            """);

        Assert.Equal(["[1,4,3]", "[16,2,3]", "opt TRUE", "opt FALSE"], twin.Pendant.Lines);
    }

    [Fact]
    public void ErrorHandler_TakesErrnoAndRetriesTrynextsAndRaises()
    {
        RapidTwinController twin = Run(
            """
              VAR num tries := 0;
              VAR num r;
              r := Divide(6, 0);
              TPWrite "trynext " \Num:=r;
              Outer;
            ERROR
              IF ERRNO = 77 THEN
                TPWrite "main got 77";
                TRYNEXT;
              ENDIF
            """,
            """
            VAR num divisor := 0;
            FUNC num Divide(num a, num b)
              RETURN a / (b + divisor);
            ERROR
              IF ERRNO = ERR_DIVZERO THEN
                divisor := 3;
                RETRY;
              ENDIF
            ENDFUNC
            PROC Outer()
              Inner;
              TPWrite "not here";
            ERROR
              TPWrite "outer passes " \Num:=ERRNO;
              RAISE;
            ENDPROC
            PROC Inner()
              RAISE 77;
            ENDPROC
            """);

        Assert.Equal(["trynext 2", "outer passes 77", "main got 77"], twin.Pendant.Lines);
    }

    [Fact]
    public void UnhandledError_StopsTheTaskWithItsLine()
    {
        RapidTwinController twin = Run("  VAR num a{2};\n  a{3} := 1;", expected: RapidProgramState.Failed);

        Assert.Equal("Execution error: line 5: the index 3 is outside the array's bounds 1..2 (task T_ROB1)", twin.Error);
        Assert.Equal(twin.Error, twin.Pendant.Lines[^1]);
    }

    [Fact]
    public void StringFunctions_FollowTheManual()
    {
        RapidTwinController twin = Run(
            """
              VAR num value;
              VAR bool ok;
              TPWrite "len " \Num:=StrLen("Robotics");
              TPWrite StrPart("Robotics", 3, 3);
              TPWrite "find " \Num:=StrFind("Robotics", 1, "bt");
              TPWrite "none " \Num:=StrFind("Robotics", 1, "xyz");
              TPWrite "match " \Num:=StrMatch("Robotics", 1, "tic");
              ok := StrToVal("-3.25E1", value);
              TPWrite "val " \Num:=value;
              ok := StrToVal("abc", value);
              TPWrite "bad " \Bool:=ok;
              TPWrite NumToStr(0.38521, 3) + " " + NumToStr(2, 3) + " " + NumToStr(-1.005, 1) + " " + NumToStr(1234.5, 0);
              TPWrite ValToStr(TRUE) + " " + ValToStr(1.5);
              TPWrite "quote "" and \\ and \41";
            """);

        Assert.Equal(["len 8", "bot", "find 3", "none 9", "match 5", "val -32.5", "bad FALSE", "0.385 2 -1 1235", "TRUE 1.5", "quote \" and \\ and A"],
            twin.Pendant.Lines);
    }

    [Fact]
    public void Motion_MovesTheArm_AndCRobTReadsItBack()
    {
        RapidTwinController twin = Run(
            """
              VAR robtarget here;
              VAR jointtarget joints;
              MoveAbsJ [[0, 0, 0, 0, 90, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0;
              MoveL [[300, 100, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, fine, tool0 \WObj:=wobj0;
              here := CRobT(\Tool:=tool0 \WObj:=wobj0);
              joints := CJointT();
              TPWrite NumToStr(here.trans.x, 2) + " " + NumToStr(here.trans.y, 2) + " " + NumToStr(here.trans.z, 2);
              TPWrite NumToStr(here.rot.q3, 4);
            """);

        Assert.Equal(["300 100 400", "1"], twin.Pendant.Lines);
        Assert.Equal(2, twin.Arm.Trace.Count(e => e.Kind == Machina.Simulation.Twin.TwinTraceKind.Motion));
        Assert.InRange((twin.Arm.Tcp.Position - new Vector(300, 100, 400)).Length, 0, 1e-6);
        // 100 mm/s with 5 m/s² ramps: MoveL covers the distance from the calibration pose to (300, 100, 400). A fine point: after a
        // zone CRobT would read the arm where it entered the zone (RapidZoneTests).
        Assert.True(twin.Clock.Seconds > 0);
    }

    [Fact]
    public void UnreachableMove_RaisesErrRoblimit_ThatAnErrorHandlerCanTake()
    {
        RapidTwinController twin = Run(
            """
              MoveL [[3000, 0, 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, z5, tool0;
              TPWrite "after";
            ERROR
              IF ERRNO = ERR_ROBLIMIT THEN
                TPWrite "handled";
                TRYNEXT;
              ENDIF
            """);

        Assert.Equal(["handled", "after"], twin.Pendant.Lines);
    }

    [Fact]
    public void SetDO_OnAConfiguredSignal_SetsIt_AndAnUnknownAliasRaisesErrAliasioDef()
    {
        var options = new RapidTwinOptions { Signals = [("DO_Gripper", "signaldo"), ("AO_Speed", "signalao")] };
        RapidTwinController twin = Run(
            """
              VAR signaldo sig;
              SetDO DO_Gripper, 1;
              SetAO AO_Speed, 2.5;
              AliasIO "DO_Gripper", sig;
              TPWrite "out " \Num:=DOutput(sig);
              AliasIO "DO_Missing", sig;
            ERROR
              TPWrite "alias error " \Bool:=ERRNO = ERR_ALIASIO_DEF;
            """, options: options);

        Assert.True(twin.Io.GetBit("do", 0));
        Assert.Equal(2.5, twin.Io.GetNumber("ao", 0));
        Assert.Equal(["out 1", "alias error TRUE"], twin.Pendant.Lines);
    }

    [Fact]
    public void DriverModules_OfDriversAbb_LoadIntoTheirTasks()
    {
        IReadOnlyDictionary<string, string> modules = AbbDriverModules.Create("127.0.0.1", 7000);
        var twin = new RapidTwinController();

        foreach ((string file, string text) in modules.Where(m => m.Key.EndsWith(".mod", StringComparison.Ordinal)))
        {
            twin.Task(file.Contains("monitor", StringComparison.Ordinal) ? "T_MACHINA_MONITOR" : RapidTwinController.MotionTask).Load([(file, text)]);
        }

        Assert.NotNull(twin.Task().Program.Find("ExecuteNext"));
        Assert.NotNull(twin.Task("T_MACHINA_MONITOR").Program.Find("Report"));
        Assert.Same(twin.Task().Program.Globals["machinaMotionId"], twin.Task("T_MACHINA_MONITOR").Program.Globals["machinaMotionId"]);
    }

    [Fact]
    public void HundredThousandLineModule_Loads()
    {
        var text = new StringBuilder("MODULE Big\n  VAR num sum := 0;\n  PROC main()\n");
        for (int i = 0; i < 100_000; i++)
        {
            text.Append("    MoveL [[300, ").Append(i % 100).Append(", 400], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]], v100, z5, tool0\\WObj:=wobj0;\n");
        }
        text.Append("  ENDPROC\nENDMODULE\n");
        var twin = new RapidTwinController();

        TimeSpan cpu = Process.GetCurrentProcess().TotalProcessorTime;
        var watch = Stopwatch.StartNew();
        twin.Load(("Big.mod", text.ToString()));
        watch.Stop();
        cpu = Process.GetCurrentProcess().TotalProcessorTime - cpu;

        // Reported, not asserted: the time depends on the machine's load (docs/simulation.md gives a quiet machine's figure).
        output.WriteLine($"100,000-line module loaded in {watch.ElapsedMilliseconds} ms ({cpu.TotalMilliseconds:0} ms of CPU, every thread)");
        Assert.Equal(100_000, twin.Task().Program.Find("main")!.Body.Count);
    }
}

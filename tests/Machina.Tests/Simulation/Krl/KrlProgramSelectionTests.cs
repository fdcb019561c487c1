using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Program selection from the submit interpreter, as KUKA's EthernetKRL server for KSS (kroshu/kuka-external-control-sdk,
/// program_handler.src) drives it: with no program selected ($PRO_STATE1 #P_FREE) its CWRITE($CMD, …, "RUN /R1/NAME()")
/// selects and starts the robot program, "STOP 1" stops it, "RESET 1" resets it and "CANCEL 1" deselects it; what the program's
/// state does not allow answers #CMD_ABORT. Before session 35 every such CWRITE stopped the program that wrote it.
/// </summary>
public class KrlProgramSelectionTests
{
    // One step per submit cycle; each step waits for the state the previous command leads to, so no step depends on timing.
    private const string Control = """
        DEF ctl( )
          SWITCH step
          CASE 0
            free0 = $PRO_STATE1 == #P_FREE
            CWRITE($CMD, st, mode, "RUN /R1/motion()")
            run_ok = st.RET1 == #CMD_OK
            step = 1
          CASE 1
            IF $PRO_STATE1 == #P_ACTIVE THEN
              CWRITE($CMD, st, mode, "CANCEL 1")
              cancel_refused = st.RET1 == #CMD_ABORT
              CWRITE($CMD, st, mode, "RUN /R1/motion()")
              run_refused = st.RET1 == #CMD_ABORT
              CWRITE($CMD, st, mode, "STOP 1")
              step = 2
            ENDIF
          CASE 2
            IF $PRO_STATE1 == #P_STOP THEN
              CWRITE($CMD, st, mode, "RESET 1")
              reset = ($PRO_STATE1 == #P_RESET) AND (st.RET1 == #CMD_OK)
              CWRITE($CMD, st, mode, "CANCEL 1")
              free1 = ($PRO_STATE1 == #P_FREE) AND (st.RET1 == #CMD_OK)
              CWRITE($CMD, st, mode, "RUN /R1/nosuch()")
              nosuch = (st.RET1 == #CMD_ABORT) AND ($PRO_STATE1 == #P_FREE)
              step = 3
            ENDIF
          ENDSWITCH
        END
        """;

    private const string ControlData = """
        DEFDAT ctl
        DECL INT step=0
        DECL BOOL free0=FALSE
        DECL BOOL run_ok=FALSE
        DECL BOOL cancel_refused=FALSE
        DECL BOOL run_refused=FALSE
        DECL BOOL reset=FALSE
        DECL BOOL free1=FALSE
        DECL BOOL nosuch=FALSE
        DECL STATE_T st
        DECL MODUS_T mode=#SYNC
        ENDDAT
        """;

    private const string Motion = "DEF motion( )\n  LOOP\n    WAIT SEC 0.012\n  ENDLOOP\nEND\n";

    [Fact]
    public async Task Cwrite_FromTheSubmitInterpreter_SelectsStartsStopsResetsAndCancelsTheRobotProgram()
    {
        using var twin = new KrlTwinController(new KrlTwinOptions { RealTime = true });
        twin.Load(("ctl.src", Control), ("ctl.dat", ControlData), ("motion.src", Motion));
        Assert.Equal("P_RESET", twin.RobotProgramState); // the first .src's program is selected by a load
        Assert.True(twin.Select(null));
        Assert.Equal("P_FREE", twin.RobotProgramState);
        using var stop = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        Task submit = Task.Run(() => twin.RunSubmit("ctl", TimeSpan.FromMilliseconds(12), stop.Token));

        KrlProgramState? run = await Task.Run(() => twin.RunNextSelected(stop.Token));
        Assert.Equal(KrlProgramState.Stopped, run);
        Assert.True(SpinWait.SpinUntil(() => Step(twin) == 3 || submit.IsCompleted, TimeSpan.FromMinutes(1)), "the submit program did not reach its last step");
        await stop.CancelAsync();
        await submit;

        Assert.Equal(3, Step(twin));
        foreach (string flag in new[] { "free0", "run_ok", "cancel_refused", "run_refused", "reset", "free1", "nosuch" })
        {
            Assert.True(Data(twin, flag) is true, flag + "\n" + string.Join("\n", twin.Pendant.Lines));
        }
        Assert.Null(twin.MainRoutine);
        Assert.Equal(
            [
                "CWRITE($CMD, …, \"CANCEL 1\") refused: the robot interpreter's program is #P_ACTIVE",
                "CWRITE($CMD, …, \"RUN /R1/motion()\") refused: the robot interpreter's program is #P_ACTIVE",
                "CWRITE($CMD, …, \"RUN /R1/nosuch()\"): program nosuch not found: no program without parameters of that name is loaded",
            ],
            twin.Pendant.Lines);
    }

    [Fact]
    public void Select_NamesTheProgramRunRuns_AndRefusesANameThatIsNoProgram()
    {
        using var twin = new KrlTwinController();
        twin.Load(("ctl.src", Control), ("ctl.dat", ControlData), ("motion.src", "DEF motion( )\n  $OUT[4] = TRUE\nEND\n"));

        Assert.False(twin.Select("nosuch"));
        Assert.Equal("ctl", twin.MainRoutine);
        Assert.True(twin.Select("motion"));
        Assert.Equal(KrlProgramState.Finished, twin.Run());
        Assert.Equal("motion", twin.MainRoutine);
        Assert.Equal("P_END", twin.RobotProgramState);
    }

    private static object Data(KrlTwinController twin, string name) => twin.Modules["ctl"].Data[name].Value;

    private static int Step(KrlTwinController twin) => Convert.ToInt32(Data(twin, "step"), System.Globalization.CultureInfo.InvariantCulture);
}

using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// More of what RAPID written by other people needs (issue 42), each in a program of our own: frame functions (RelTool, OrientZYX,
/// EulerZYX, PoseMult, PoseInv, PoseVect), late binding, the pendant's dialogs without an operator, signals read as values, group
/// signals, the USER system module's data, EIO.cfg signals, and MultiMove refused by name.
/// </summary>
public class RapidForeignLibraryTests
{
    private static RapidTwinController Run(string body, string data = "", (string, string)[]? signals = null)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Signals = signals ?? [] });
        twin.Load(("T.mod", $"MODULE T\n{data}\nPROC main()\n{body}\nENDPROC\nENDMODULE\n"));
        RapidProgramState state = twin.Run();
        Assert.True(state == RapidProgramState.Finished, $"{state}: {twin.Error}");
        return twin;
    }

    private const string Writers = """
        PROC W(string s, orient q)
          TPWrite s + NumToStr(q.q1, 4) + "," + NumToStr(q.q2, 4) + "," + NumToStr(q.q3, 4) + "," + NumToStr(q.q4, 4);
        ENDPROC
        PROC P(string s, pos p)
          TPWrite s + NumToStr(p.x, 3) + "," + NumToStr(p.y, 3) + "," + NumToStr(p.z, 3);
        ENDPROC
        """;

    [Fact]
    public void FrameFunctions_AgreeWithHandDerivedQuaternionsAndPoses()
    {
        RapidTwinController twin = Run(
            """
              VAR robtarget down := [[100, 0, 0], [0, 1, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
              VAR robtarget moved;
              VAR pose rz := [[10, 0, 0], [0.7071068, 0, 0, 0.7071068]];
              W "z90 ", OrientZYX(90, 0, 0);
              W "y90 ", OrientZYX(0, 90, 0);
              TPWrite "zyx " + NumToStr(EulerZYX(\Z, OrientZYX(30, 20, 10)), 3) + "," + NumToStr(EulerZYX(\Y, OrientZYX(30, 20, 10)), 3) + ","
                + NumToStr(EulerZYX(\X, OrientZYX(30, 20, 10)), 3);
              moved := RelTool(down, 0, 0, 10 \Rz:=90);
              P "reltool ", moved.trans;
              W "reltool ", moved.rot;
              P "mult ", PoseMult([[1, 2, 3], [1, 0, 0, 0]], rz).trans;
              P "inv ", PoseInv(rz).trans;
              W "inv ", PoseInv(rz).rot;
              P "vect ", PoseVect(rz, [1, 0, 0]);
            """,
            Writers);

        // Rz(90) = [cos 45°, 0, 0, sin 45°]; a tool turned 180° about x points down, so +10 mm along its z is -10 mm in z, and a
        // further 90° about its z is [0, 1, 0, 0] * [c, 0, 0, s] = [0, c, -s, 0]. The inverse of (10, 0, 0) turned 90° about z is
        // (0, 10, 0) turned -90°; (1, 0, 0) in that frame is (10, 1, 0).
        Assert.Equal(
            [
                "z90 0.7071,0,0,0.7071", "y90 0.7071,0,0.7071,0", "zyx 30,20,10", "reltool 100,0,-10", "reltool 0,0.7071,-0.7071,0",
                "mult 11,2,3", "inv 0,10,0", "inv 0.7071,0,0,-0.7071", "vect 10,1,0",
            ],
            twin.Pendant.Lines);
    }

    [Fact]
    public void LateBinding_CallsTheProcedureItsStringNames_AndAnUnknownOneRaisesErrRefunkprc()
    {
        RapidTwinController twin = Run(
            """
              VAR string n := "Two";
              %"Proc" + n% 5;
              IF TRUE %"ProcOne"%;
              %"Nope"%;
              TPWrite "end";
            ERROR
              TPWrite "unknown " \Bool:=ERRNO = ERR_REFUNKPRC;
              TRYNEXT;
            """,
            """
            PROC ProcOne()
              TPWrite "one";
            ENDPROC
            PROC ProcTwo(num x)
              TPWrite "two " \Num:=x;
            ENDPROC
            """);

        Assert.Equal(["two 5", "one", "unknown TRUE", "end"], twin.Pendant.Lines);
    }

    [Fact]
    public void Dialogs_WithoutAnOperator_AnswerTheirDefault_AndSaySo()
    {
        RapidTwinController twin = Run(
            """
              VAR btnres a;
              VAR num k;
              a := UIMessageBox(\Header:="Cell" \Message:="Go on?" \Buttons:=btnYesNo);
              TPWrite "a " \Num:=a;
              a := UIMessageBox(\MsgArray:=[stEmpty, "x"] \BtnArray:=["A", "B"] \DefaultBtn:=2);
              TPWrite "b " \Num:=a;
              TPWrite "n " \Num:=UINumEntry(\Message:="How many?" \InitValue:=7 \MinValue:=1);
              TPReadFK k, "Pick", stEmpty, "Left", "Right", stEmpty, stEmpty;
              TPWrite "k " \Num:=k;
            """);

        Assert.Equal(
            [
                "UIMessageBox \"Go on?\": no operator at the pendant, answered BTN_YES (line 6)", "a 6",
                "UIMessageBox \"\": no operator at the pendant, answered button 2 (line 8)", "b 2",
                "UINumEntry \"How many?\": no operator at the pendant, answered 7 (line 10)", "n 7",
                "TPReadFK \"Pick\": no operator at the pendant, answered function key 2 (\"Left\") (line 11)", "k 2",
            ],
            twin.Pendant.Lines);
    }

    [Fact]
    public void Signals_ReadAsValues_GroupSignals_AndTheUserModulesRegisters()
    {
        RapidTwinController twin = Run(
            """
              SetDO do1, 1;
              SetGO go1, 13;
              reg1 := do1 + gi1;
              IF do1 = 1 AND di1 = 0 TPWrite "do1 on, di1 off";
              TPWrite "reg1 " \Num:=reg1;
              TPWrite "go1 " \Num:=GOutput(go1);
              IF NOT RobOS() TPWrite "virtual controller";
              ClkStart clock1;
            """,
            signals: [("do1", "signaldo"), ("di1", "signaldi"), ("go1", "signalgo"), ("gi1", "signalgi")]);

        Assert.Equal(["do1 on, di1 off", "reg1 1", "go1 13", "virtual controller"], twin.Pendant.Lines);
    }

    [Fact]
    public void UserModule_OfTheProgram_TakesThePlaceOfThePredefinedRegisters()
    {
        var twin = new RapidTwinController();
        twin.Load(("user.sys", "MODULE user(SYSMODULE)\nVAR num reg1 := 4;\nVAR clock clock1;\nENDMODULE\n"),
            ("T.mod", "MODULE T\nPROC main()\nTPWrite \"reg1 \" \\Num:=reg1;\nENDPROC\nENDMODULE\n"));

        Assert.Equal(RapidProgramState.Finished, twin.Run());
        Assert.Equal(["reg1 4"], twin.Pendant.Lines);
    }

    [Fact]
    public void EioConfig_ReadsEachSignalsNameTypeAndDefault_AndNothingOutsideEioSignal()
    {
        const string text = """
            EIO:CFG_1.0:5:60::
            #
            EIO_UNIT:

                  -Name "BOARD1" -UnitType "d652" -Bus "DeviceNet1"
            #
            EIO_SIGNAL:

                  -Name "doGripper" -SignalType "DO" -Unit "BOARD1" -UnitMap "0"\
                  -Access "All"

                  -Name "diPart" -SignalType "DI" -Unit "BOARD1" -UnitMap "1" -Default "1"

                  -Name "giRecipe" -SignalType "GI" -Unit "BOARD1" -UnitMap "8-15"
            #
            EIO_CROSS:

                  -Res "diPart" -Act1 "doGripper"
            """;

        Assert.Equal([("doGripper", "signaldo", 0.0), ("diPart", "signaldi", 1.0), ("giRecipe", "signalgi", 0.0)], RapidEioConfig.Signals(text));
    }

    [Fact]
    public void SyncMoveOn_Loads_AndStopsTheTaskByName_ForTheTwinMovesOneRobot()
    {
        var twin = new RapidTwinController();
        twin.Load(("T.mod", """
            MODULE T
            PERS tasks both{2} := [["T_ROB_L"], ["T_ROB_R"]];
            VAR syncident sync1;
            PROC main()
              SyncMoveOn sync1, both;
            ERROR
              TPWrite "handled";
            ENDPROC
            ENDMODULE
            """));

        Assert.Equal(RapidProgramState.Failed, twin.Run());
        Assert.Equal(
            "Execution error: line 5: SyncMoveOn: the twin moves one robot (ABB IRB 120); synchronized motion of several robots (MultiMove) is not supported (task T_ROB1)",
            twin.Error);
        Assert.DoesNotContain("handled", twin.Pendant.Lines);
    }

    [Fact]
    public void CToolCWObjAndCPos_TellTheLastMotionsToolAndWorkObject_AndWhereItsTcpIs()
    {
        RapidTwinController twin = Run(
            """
              t := CTool();
              TPWrite "before: tool0 " \Bool:=t.tframe.trans.z = 0;
              p := CRobT(\Tool:=gripper \WObj:=table);
              MoveL p, v100, fine, gripper \WObj:=table;
              t := CTool();
              w := CWObj();
              TPWrite "tool z " \Num:=t.tframe.trans.z;
              TPWrite "wobj x " \Num:=w.uframe.trans.x;
              here := CPos();
              flange := CPos(\Tool:=tool0 \WObj:=wobj0);
              TPWrite "dz " \Num:=Round(flange.z - here.z \Dec:=3);
              TPWrite "dx " \Num:=Round(flange.x - here.x \Dec:=3);
            """,
            """
            PERS tooldata gripper := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 50], [1, 0, 0, 0], 0, 0, 0]];
            PERS wobjdata table := [FALSE, TRUE, "", [[10, 20, 30], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
            VAR robtarget p;
            VAR pos here;
            VAR pos flange;
            VAR tooldata t;
            VAR wobjdata w;
            """);

        // The wrist points down: the gripper's TCP is 100 mm below the flange, and the table's frame is 10, 20, 30 mm off the base.
        Assert.Equal(["before: tool0 TRUE", "tool z 100", "wobj x 10", "dz 130", "dx 10"], twin.Pendant.Lines);
    }
}

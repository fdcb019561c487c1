using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// Session 35 (perf55r, issue 45): a data cell counts its writes, a move whose tooldata and wobjdata were read from the same data,
/// not written since, takes the last move's frames without comparing them, an aggregate assigned to VAR record data is written into
/// the record the data hold, and RWS reads a value as one state of it. Every way of writing the data must make the next move read
/// them again, and the values must be what a new record gives.
/// </summary>
public class RapidCellWriteTests
{
    private static RapidTwinController Load(string module)
    {
        var twin = new RapidTwinController(new RapidTwinOptions { Model = RobotModels.Get("IRB 1600-8/1.45") });
        twin.Load(("T.mod", module));
        return twin;
    }

    private static IReadOnlyList<string> Run(RapidTwinController twin)
    {
        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        return twin.Pendant.Lines;
    }

    [Fact]
    public void EveryWayOfWritingTheTool_MovesTheFlange_AtTheNextMove()
    {
        // The flange's z is the target's 558 plus the tool's z (the target's orientation turns the tool down), x the work object's.
        IReadOnlyList<string> lines = Run(Load(
            """
            MODULE T
            VAR tooldata vtool := [TRUE, [[0, 0, 100], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
            VAR tooldata tools{2};
            VAR wobjdata vwobj := [FALSE, TRUE, "", [[10, 0, 0], [1, 0, 0, 0]], [[0, 0, 0], [1, 0, 0, 0]]];
            VAR robtarget p := [[303, 0, 558], [0, 0, 1, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
            VAR num i := 1;
            PROC main()
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              Flange "first";
              Lengthen vtool, 150;
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              Flange "inout";
              vtool.tframe.trans := [0, 0, 250];
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              Flange "aggregate";
              vwobj.uframe := [[20, 0, 0], [1, 0, 0, 0]];
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              Flange "wobj aggregate";
              tools{1} := vtool;
              tools{1}.tframe.trans.z := 10;
              tools{2} := tools{1};
              MoveL p, v100, fine, tools{i} \WObj:=vwobj;
              Flange "element";
              tools{1}.tframe.trans.z := 20;
              MoveL p, v100, fine, tools{i} \WObj:=vwobj;
              Flange "element changed";
              i := 2;
              tools{2}.tframe.trans.z := 30;
              MoveL p, v100, fine, tools{i} \WObj:=vwobj;
              Flange "other element";
              tools{2} := [TRUE, [[0, 0, 40], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
              MoveL p, v100, fine, tools{i} \WObj:=vwobj;
              Flange "element aggregate";
              SetDataVal "vtool", tools{1};
              MoveL p, v100, fine, vtool \WObj:=vwobj;
              Flange "setdataval";
              Twice;
            ENDPROC
            PROC Twice()
              VAR tooldata own := [TRUE, [[0, 0, 60], [1, 0, 0, 0]], [1, [0, 0, 1], [1, 0, 0, 0], 0, 0, 0]];
              MoveWith own;
              Flange "in parameter";
              own.tframe.trans.z := 70;
              MoveWith own;
              Flange "in parameter changed";
            ENDPROC
            PROC MoveWith(tooldata t)
              MoveL p, v100, fine, t \WObj:=vwobj;
            ENDPROC
            PROC Lengthen(INOUT tooldata t, num z)
              t.tframe.trans.z := z;
            ENDPROC
            PROC Flange(string label)
              VAR robtarget f;
              f := CRobT(\Tool:=tool0 \WObj:=wobj0);
              TPWrite label + " " + NumToStr(f.trans.x, 1) + " " + NumToStr(f.trans.z, 1);
            ENDPROC
            ENDMODULE
            """));

        Assert.Equal(["first 313 658", "inout 313 708", "aggregate 313 808", "wobj aggregate 323 808", "element 323 568",
            "element changed 323 578", "other element 323 588", "element aggregate 323 598", "setdataval 323 578",
            "in parameter 323 618", "in parameter changed 323 628"], lines);
    }

    [Fact]
    public void AnAggregateAssignedToVarRecordData_IsWrittenIntoTheRecordTheyHold_WithTheValueANewRecordGives()
    {
        RapidTwinController twin = Load(
            """
            MODULE T
            VAR robtarget g := [[1, 2, 3], [1, 0, 0, 0], [0, 0, 0, 0], [9E9, 9E9, 9E9, 9E9, 9E9, 9E9]];
            VAR pos list{2};
            VAR pos h;
            VAR pos q := [4, 5, 6];
            VAR pose nested;
            PERS pos shared := [0, 0, 0];
            PROC main()
              VAR num n := 0;
              g.trans := [g.trans.y, g.trans.x, g.trans.z + 1];
              list{2} := [7, 8, 9];
              list{1} := list{2};
              list{2} := [list{2}.z, 0, F()];
              nested := [q, [1, 0, 0, 0]];
              q.x := 40;
              shared := [1, 1, 1];
              TPWrite ValToStr(g.trans) + ValToStr(list{1}) + ValToStr(list{2}) + ValToStr(h) + ValToStr(nested) + ValToStr(shared);
              list{n + 3} := [1, 1, 1];
            ERROR
              TPWrite "error " + NumToStr(ERRNO, 0);
              list{1} := [5, 5, 5];
              TPWrite ValToStr(list{1});
            ENDPROC
            FUNC num F()
              h := [11, 12, 13];
              RETURN h.y;
            ENDFUNC
            ENDMODULE
            """);
        var g = (RapidRecord)twin.FindData("T_ROB1", "T", "g")!.Value;
        var list = (RapidArray)twin.FindData("T_ROB1", "T", "list")!.Value;
        object gTrans = g.Fields[0], list2 = list.Items[1];
        long before = twin.FindData("T_ROB1", "T", "list")!.Version;

        Assert.Equal(["[2,1,4][7,8,9][9,0,12][11,12,13][[4,5,6],[1,0,0,0]][1,1,1]", "error 41003", "[5,5,5]"], Run(twin));
        Assert.Same(gTrans, g.Fields[0]); // written in place: the record g held, not a new one
        Assert.Same(list2, list.Items[1]);
        Assert.True(twin.FindData("T_ROB1", "T", "list")!.Version > before);
    }

    [Fact]
    public void AMarkOfARead_IsTheSameOnlyWhileTheCellHoldsTheSameValueUnwritten()
    {
        var value = new RapidRecord(RapidTypes.Pos, [1.0, 2.0, 3.0]);
        var cell = new RapidCell("p", new RapidDataType(RapidTypes.Pos), RapidStorage.Var, value);
        var first = new RapidCellMark(cell, value, cell.Version);

        Assert.True(first.Same(new RapidCellMark(cell, value, cell.Version)));
        Assert.False(first.Same(new RapidCellMark(null, value, cell.Version)));
        Assert.False(new RapidCellMark(null, value, 0).Same(new RapidCellMark(null, value, 0))); // no data's value: never the same
        cell.Written(); // a component written in place
        Assert.False(first.Same(new RapidCellMark(cell, value, cell.Version)));
        long written = cell.Version;
        cell.BeginWrite();
        Assert.Equal(written + 1, cell.Version); // odd while several parts are written
        cell.EndWrite();
        Assert.Equal(written + 2, cell.Version);
        cell.Value = value; // the same record given again (a routine's kept record)
        Assert.Equal(written + 4, cell.Version);
    }

    [Fact]
    public void ARead_IsTakenAgain_WhenTheValueIsWrittenMeanwhile_AndGivesUpWhileAWriteNeverEnds()
    {
        var value = new RapidRecord(RapidTypes.Pos, [1.0, 2.0, 3.0]);
        var cell = new RapidCell("p", new RapidDataType(RapidTypes.Pos), RapidStorage.Var, value);
        int reads = 0;

        string? text = cell.Read(v =>
        {
            string seen = RapidValues.ToText(v);
            if (++reads == 1)
            {
                // The task writes two components while the first read formats the value: that text is of no one state.
                cell.BeginWrite();
                value.Fields[0] = 10.0;
                value.Fields[1] = 20.0;
                cell.EndWrite();
            }
            return seen;
        });

        Assert.Equal("[10,20,3]", text);
        Assert.Equal(2, reads);
        cell.BeginWrite();
        Assert.Null(cell.Read(RapidValues.ToText));
    }
}

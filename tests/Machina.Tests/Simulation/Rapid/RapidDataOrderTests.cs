using Machina.Simulation.Rapid;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// A task's modules are linked together before they run: module data may name data that a later module or a later line declares
/// (an array sized by a CONST of another module, as a published calibration program does with its <c>calibVars</c> module).
/// </summary>
public class RapidDataOrderTests
{
    [Fact]
    public void AnArraySizedByAConstOfALaterModule_Loads()
    {
        var twin = new RapidTwinController();
        twin.Load(
            ("Main.mod", """
                MODULE Main
                  PERS robtarget saved{size};
                  VAR num twice := size * 2;
                  PROC main()
                    TPWrite "saved " \Num:=Dim(saved, 1);
                    TPWrite "twice " \Num:=twice;
                    TPWrite "kept " \Num:=kept{2};
                  ENDPROC
                ENDMODULE
                """),
            ("Vars.mod", """
                MODULE Vars
                  VAR num kept{size} := [1, 2, 3];
                  CONST num size := base + 1;
                  CONST num base := 2;
                ENDMODULE
                """));

        Assert.True(twin.Run() == RapidProgramState.Finished, twin.Error);
        Assert.Equal(["saved 3", "twice 6", "kept 2"], twin.Pendant.Lines);
    }

    [Fact]
    public void DataThatNameEachOther_AreRefusedWithTheFirstOnesReferenceError()
    {
        var twin = new RapidTwinController();

        var error = Assert.Throws<RapidLoadException>(() => twin.Load(("T.mod", "MODULE T\n  VAR num a := b;\n  VAR num b := a;\n  PROC main()\n  ENDPROC\nENDMODULE\n")));

        Assert.Equal("Load error: line 2: Reference error: 'b' is unknown (not data)", error.Message);
    }

    [Fact]
    public void DataOfNoModule_AreStillRefusedWithTheirLine()
    {
        var twin = new RapidTwinController();

        var error = Assert.Throws<RapidLoadException>(() => twin.Load(("T.mod", "MODULE T\n  VAR num ok := 1;\n  VAR num a{missing};\n  PROC main()\n  ENDPROC\nENDMODULE\n")));

        Assert.Equal("Load error: line 3: Reference error: 'missing' is unknown (not data)", error.Message);
    }
}

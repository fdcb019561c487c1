using Machina.Simulation.Krl;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// Declarations of published programs (issue 43): their own STRUC and ENUM types across files, array elements given in a data
/// list, and TRIGGER bound to the next motion.
/// </summary>
public class KrlDeclarationTests
{
    private const string Types = """
        DEFDAT types PUBLIC
          GLOBAL STRUC Cmd INT code, REAL speed, CHAR name[8], Mode how
          GLOBAL ENUM Mode IDLE, RUNNING
          DECL GLOBAL Mode state = #IDLE
          DECL GLOBAL INT codes[3]
          codes[2] = 7
          DECL GLOBAL Cmd last
        ENDDAT
        """;

    [Fact]
    public void StrucAndEnumOfAnotherFile_AndDataListElements_LoadAndRun()
    {
        const string source = """
            DEF prog( )
              DECL Cmd c
              c.code = codes[2]
              c.speed = 0.5
              c.how = #RUNNING
              state = c.how
              SWITCH state
                CASE #RUNNING
                  $OUT[3] = TRUE
                DEFAULT
                  $OUT[4] = TRUE
              ENDSWITCH
              last = c
            END
            """;
        using var twin = new KrlTwinController();
        // prog.src is read before types.dat, whose types it uses.
        twin.Load(("prog.src", source), ("types.src", "DEF types( )\nEND\n"), ("types.dat", Types));

        Assert.True(twin.Run() == KrlProgramState.Finished, twin.Error);
        var last = (KrlStructValue)twin.Modules["types"].Data["last"].Value;
        Assert.Equal("Cmd", last.Type.Name);
        Assert.Equal(7, (int)last.Values[0]);
        Assert.Equal(0.5, (double)last.Values[1], 6);
        Assert.Equal(new KrlEnumValue("RUNNING"), last.Values[3]);
        object[] outputs = ((KrlArrayValue)twin.Environment.System["$OUT"].Value).ToObjects();
        Assert.True((bool)outputs[2]);
        Assert.False((bool)outputs[3]);
    }

    [Theory]
    [InlineData("DEFDAT prog\n  STRUC Pair INT a, Unknown b\nENDDAT\n", 2, "unknown data type 'Unknown' in STRUC Pair")]
    [InlineData("DEFDAT prog\n  DECL INT codes[3]\n  codes[4] = 1\nENDDAT\n", 3, "index 4 of codes is outside 1 to 3")]
    [InlineData("DEFDAT prog\n  other[1] = 1\nENDDAT\n", 2, "other is not an array declared in the data list")]
    public void ADeclarationTheTwinCannotMake_IsRefusedAtLoad_WithFileLineAndName(string data, int line, string reason)
    {
        using var twin = new KrlTwinController();
        KrlLoadException ex = Assert.Throws<KrlLoadException>(() => twin.Load(("prog.src", "DEF prog( )\nEND\n"), ("prog.dat", data)));

        Assert.Equal("prog.dat", ex.File);
        Assert.Equal(line, ex.Line);
        Assert.Equal($"prog.dat, line {line}: {reason}", ex.Message);
    }

    [Fact]
    public void Trigger_RunsItsActionAtTheStartOrTheEndOfTheNextMotion()
    {
        const string source = """
            DEF prog( )
              PTP {AXIS: A1 0, A2 -90, A3 90, A4 0, A5 30, A6 0}
              TRIGGER WHEN DISTANCE=1 DELAY=0 DO mark( ) PRIO=-1
              TRIGGER WHEN DISTANCE=0 DELAY=0 DO $OUT[1] = TRUE
              $OUT[2] = TRUE
              PTP {AXIS: A1 20, A2 -90, A3 90, A4 0, A5 30, A6 0}
              $OUT[4] = TRUE
            END

            DEF mark( )
              $OUT[3] = TRUE
            END
            """;
        using var twin = new KrlTwinController();
        twin.Load(("prog.src", source));

        Assert.True(twin.Run() == KrlProgramState.Finished, twin.Error);
        string[] order = [.. twin.Arm.Trace.Where(e => e.Kind is TwinTraceKind.Output or TwinTraceKind.Motion).Select(e => e.Text)];
        Assert.Equal(["PTP (BCO run)", "$OUT[2] = TRUE", "$OUT[1] = TRUE", "PTP", "$OUT[3] = TRUE", "$OUT[4] = TRUE"], order);
    }
}

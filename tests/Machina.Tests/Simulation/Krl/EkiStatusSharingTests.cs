using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>
/// The EKI_ functions hand out the same status structure for the same result (the twin keeps them); a program that writes a
/// component of the one its variable holds changes only its own copy: later calls and other variables still read the status.
/// </summary>
public class EkiStatusSharingTests
{
    [Fact]
    public void StatusComponentWritten_LaterCallsAndOtherVariablesKeepTheirValues()
    {
        const string Program = """
            DEF shared( )
              DECL EKI_STATUS ret, again, kept
              ret = EKI_Init("Shared")
              ret = EKI_CheckBuffer("Shared", "Cmd/@A")
              kept = ret
              again = EKI_CheckBuffer("Shared", "Cmd/@A")
              ret.Buff = 99
              ret.Msg_No = 7
              again = EKI_CheckBuffer("Shared", "Cmd/@A")
              got[1] = ret.Buff
              got[2] = ret.Msg_No
              got[3] = again.Buff
              got[4] = again.Msg_No
              got[5] = kept.Buff
              again.Buff = 5
              ret = EKI_CheckBuffer("Shared", "Cmd/@A")
              got[6] = ret.Buff
              got[7] = again.Buff
            END
            """;
        const string Data = "DEFDAT shared\n  DECL INT got[7]\nENDDAT\n";
        using var twin = new KrlTwinController();
        twin.AddEkiConfiguration("Shared", "<ETHERNETKRL><CONFIGURATION><EXTERNAL><TYPE>Client</TYPE></EXTERNAL><INTERNAL><PORT>0</PORT></INTERNAL></CONFIGURATION><RECEIVE><XML><ELEMENT Tag=\"Cmd/@A\" Type=\"INT\" /></XML></RECEIVE></ETHERNETKRL>");
        twin.Load(("shared.src", Program), ("shared.dat", Data));

        KrlProgramState state = twin.Run();

        Assert.True(state == KrlProgramState.Finished, $"{state}: {twin.Error}");
        object[] got = ((KrlArrayValue)twin.Modules["shared"].Data["got"].Value).ToObjects();
        Assert.Equal([99, 7, 0, 0, 0, 0, 5], got.Select(o => (int)o));
    }
}

using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Tests.Simulation.Rapid;

/// <summary>
/// What Machina's RAPID driver (drivers/abb/machina_abb_driver.mod) runs per streamed request, counted by the RAPID twin's step budget
/// (<see cref="TwinLimits.MaxSteps"/>: every statement and loop turn), and the request values and acknowledgements of the paths that
/// run fewer statements since session 33 (issue 45): a request of numbers buffered in place, its unused slots cleared only when an
/// earlier request used them, the acknowledgement of a request with an id in one condition.
/// </summary>
public class RapidDriverStepTests
{
    /// <summary>The streamed requests, eight at a time, cut into chunks of at most 80 characters as SocketReceive hands them over.</summary>
    private static List<string> Chunks()
    {
        var chunks = new List<string>();
        for (int batch = 0; batch < 3; batch++)
        {
            var text = new StringBuilder();
            for (int k = 0; k < 8; k++)
            {
                int id = 1001 + batch * 8 + k;
                text.Append('@').Append(id).Append(" 1 ").Append(id % 2 == 0 ? 303 : 302).Append(" 0 558 0 0 1 0;");
            }
            string all = text.ToString();
            for (int at = 0; at < all.Length; at += 80)
            {
                chunks.Add(all.Substring(at, Math.Min(80, all.Length - at)));
            }
        }
        return chunks;
    }

    /// <summary>
    /// Runs <paramref name="rounds"/> times <paramref name="chunks"/> through the driver's ParseChunk and ExecuteNext, with a host
    /// connected on loopback, under a budget of <paramref name="steps"/> (0: none); returns the task's state and what the host received.
    /// </summary>
    private static (RapidProgramState State, string Received, RapidTwinController Twin) Stream(List<string> chunks, int rounds, long steps)
    {
        var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        string probe = $$"""
            MODULE StepProbe
            CONST string CH{{{chunks.Count}}} := [{{string.Join(", ", chunks.Select(c => "\"" + c + "\""))}}];
            PROC Probe()
            SocketCreate serverSocket;
            SocketBind serverSocket, "127.0.0.1", {{port}};
            SocketListen serverSocket;
            SocketAccept serverSocket, clientSocket \Time:=10;
            clientConnected := TRUE;
            InitializeState;
            cursorSpeed := [200, 500, 5000, 1000];
            FOR k FROM 1 TO {{rounds}} DO
            FOR c FROM 1 TO {{chunks.Count}} DO
            ParseChunk CH{c};
            WHILE requestCount > 0 DO
            ExecuteNext;
            ENDWHILE
            ENDFOR
            ENDFOR
            SocketClose clientSocket;
            SocketClose serverSocket;
            TPWrite "executed " + ValToStr(lastExecutedId) + " received " + ValToStr(lastReceivedId);
            ENDPROC
            ENDMODULE
            """;
        var twin = new RapidTwinController(new RapidTwinOptions
        {
            Model = RobotModels.Get("IRB 1600-8/1.45"),
            RealTime = false,
            Limits = new TwinLimits { MaxSteps = steps },
        });
        twin.Reserve(listener);
        twin.Load(("machina_abb_driver.mod", AbbDriverModules.Create("127.0.0.1", port)["machina_abb_driver.mod"]), ("StepProbe.mod", probe));
        using var host = new TcpClient();
        host.Connect(IPAddress.Loopback, port);
        using var cancel = new CancellationTokenSource(TimeSpan.FromSeconds(60));
        Task<string> received = Task.Run(async () =>
        {
            using var reader = new StreamReader(host.GetStream(), Encoding.ASCII);
            return await reader.ReadToEndAsync(cancel.Token);
        });
        RapidProgramState state = twin.Run("Probe");
        Assert.True(received.Wait(TimeSpan.FromSeconds(60)), "the host's read to end");
        return (state, received.Result, twin);
    }

    [Fact]
    public void StreamedMoveL_RunsAtMost89StatementsAndLoopTurnsPerRequest_AcknowledgingEachInOrder()
    {
        const int Rounds = 20;
        // 100 steps for the probe's own set-up (it takes 35), then 89 per request: the driver of session 32 ran 92.3 per request
        // (and stops at this budget, 44,353 steps in all), session 33's runs 85.2.
        (RapidProgramState state, string received, RapidTwinController twin) = Stream(Chunks(), Rounds, 100 + Rounds * 24 * 89);

        Assert.Null(twin.Error);
        Assert.Equal(RapidProgramState.Finished, state);
        var expected = new StringBuilder();
        for (int round = 0; round < Rounds; round++)
        {
            for (int id = 1001; id <= 1024; id++)
            {
                expected.Append('@').Append(id).Append(" 1;");
            }
        }
        Assert.Equal(expected.ToString(), received);
        // The last request (id 1024) moved the flange to x 303.
        Vector flange = twin.Arm.FlangeAt(twin.Arm.Joints).Position;
        Assert.Equal([303.0, 0, 558], new[] { flange.X, flange.Y, flange.Z }.Select(v => Math.Round(v, 3)));
        Assert.Equal("executed 1024 received 1024", twin.Pendant.Lines[^1]);
    }

    [Fact]
    public void RequestsWithIdZeroOrANegativeId_AreAcknowledgedAsBefore_AndLeaveTheProgressAlone()
    {
        // Speed requests read whole: id 0 is acknowledged "code;", a negative id "@id code;"; only ids above 0 are progress ($25).
        (RapidProgramState state, string received, RapidTwinController twin) = Stream(["@7 4 100;@0 4 200;@-5 4 300;"], 1, 0);

        Assert.Null(twin.Error);
        Assert.Equal(RapidProgramState.Finished, state);
        Assert.Equal("@7 4;4;@-5 4;", received);
        Assert.Equal("executed 7 received 7", twin.Pendant.Lines[^1]);
    }

    [Fact]
    public void ARequestAfterALongerOrARefusedOne_ReadsTheParametersItDoesNotGiveAsZero()
    {
        // @1 gives all eleven parameters, @2 seven. The whole read of @3 stores eleven numbers before its twelfth, "1.1.1", fails;
        // the token parser then refuses @3 (USE_STRICT FALSE: complained about, dropped), and @4 gives one parameter.
        const string Probe = """
            MODULE ValuesProbe
            PROC Probe()
            USE_STRICT := FALSE;
            ParseChunk "@1 8 1 2 3 4 5 6 7 8 9 10 11;@2 1 5 6 7 8 9 10 11;";
            ParseChunk "@3 8 1 2 3 4 5 6 7 8 9 10 1.1.1;@4 4 100;";
            WHILE requestCount > 0 DO
            TPWrite ValToStr(requests{readIndex});
            readIndex := readIndex MOD BUFFER_SIZE + 1;
            requestCount := requestCount - 1;
            ENDWHILE
            ENDPROC
            ENDMODULE
            """;
        var twin = new RapidTwinController();
        twin.Load(("machina_abb_driver.mod", AbbDriverModules.Create("127.0.0.1", 1000)["machina_abb_driver.mod"]), ("ValuesProbe.mod", Probe));

        Assert.Equal(RapidProgramState.Finished, twin.Run("Probe"));
        Assert.Null(twin.Error);
        Assert.Equal(
        [
            "1.1.1", "Machina: received corrupt value", "Machina: received corrupt request",
            "[1,8,\"\",1,2,3,4,5,6,7,8,9,10,11]",
            "[2,1,\"\",5,6,7,8,9,10,11,0,0,0,0]",
            "[4,4,\"\",100,0,0,0,0,0,0,0,0,0,0]",
        ], twin.Pendant.Lines);
    }
}

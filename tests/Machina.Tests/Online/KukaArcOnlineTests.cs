using System.Text;
using Machina.Simulation;
using Machina.Simulation.Krl;
using static Machina.Tests.Online.ArcOnlineSupport;
using static Machina.Tests.Online.KukaTestSupport;
using static Machina.Tests.Online.OnlineTestSupport;

namespace Machina.Tests.Online;

/// <summary>
/// Arcs online on KUKA (issue 46): the driver's CIRC action (T="17") carries the target in V1 … V6 and the auxiliary point in
/// V8 … V13 as the KRL compiler writes them, and an arc streamed to the KRL twin ends where the compiled program ends on it.
/// </summary>
public class KukaArcOnlineTests
{
    /// <summary>From a joint position, two straight moves with the tool down, then an arc down to the paper.</summary>
    private const string Program = """
        SpeedTo(100);
        AxesTo(0, -90, 90, 0, 90, 0);
        MoveTo(400, -100, 400);
        Move(0, 0, -100);
        ArcMotionTo(475, 0, 360, 400, 100, 300);
        Wait(100);
        """;

    [Fact]
    public void Encode_ArcMotion_TargetInV1ToV6_AuxiliaryPointInV8ToV13()
    {
        var cursor = new RobotCursor();
        Assert.Null(cursor.TryApply(new ActionTransformation(new Vector(400, -100, 300), Rotation.FlippedAroundY, false, true) { Id = 1 }));
        RobotAction arc = Instructions.Parse("ArcMotionTo(475.25, 0, 360, 400, 100, 300.5);")[0];
        arc.Id = 2;
        Assert.Null(cursor.TryApply(arc));

        var sb = new StringBuilder();
        KukaActionEncoder.Encode(arc, 2, cursor)!.Value.AppendTo(sb);

        Assert.Equal("<A ID=\"2\" T=\"17\" V1=\"400\" V2=\"100\" V3=\"300.5\" V4=\"180\" V5=\"0\" V6=\"180\" V7=\"0\""
            + " V8=\"475.25\" V9=\"0\" V10=\"360\" V11=\"180\" V12=\"0\" V13=\"180\" M=\"\"/>", sb.ToString());
        Assert.Null(new KukaOnline().WhyCannotStream(arc));
    }

    [Fact]
    public void Parse_CircularElement_ReadsThirteenValues_OtherActionsSeven()
    {
        var reader = new KukaXmlReader();
        reader.Append(Encoding.ASCII.GetBytes("<DT><DR><A ID=\"4\" T=\"17\" V1=\"1\" V2=\"2\" V3=\"3\" V4=\"4\" V5=\"5\" V6=\"6\" V7=\"0\""
            + " V8=\"8\" V9=\"9\" V10=\"10\" V11=\"11\" V12=\"12\" V13=\"13\" M=\"\"/><A ID=\"5\" T=\"7\" V1=\"1.5\" V2=\"0\" V3=\"0\" V4=\"0\" V5=\"0\" V6=\"0\" V7=\"0\" M=\"\"/></DR></DT>"));
        Assert.True(reader.TryRead(out KukaElement batch));
        KukaElement[] actions = [.. batch.Children.Single().Children];

        KukaInstruction circ = KukaInstruction.Parse(actions[0]), wait = KukaInstruction.Parse(actions[1]);

        Assert.Equal((4, KukaActionCode.Circular), (circ.Id, circ.Code));
        KukaValues v = circ.Values;
        Assert.Equal([1, 2, 3, 4, 5, 6, 0, 8, 9, 10, 11, 12, 13], Enumerable.Range(0, KukaProtocol.CircularValueCount).Select(i => v[i]));
        Assert.Equal((KukaActionCode.Wait, 1.5), (wait.Code, wait.Values[0]));
    }

    [Fact]
    public void DriverSrc_ReadsTheAuxiliaryPointOnlyForACirc_AndRunsCircAsTheCompiler()
    {
        string src = KukaDriverModules.Read("machina_kuka_driver.src");
        Assert.Contains("DECL REAL slot_v[100,13]", KukaDriverModules.Read("machina_kuka_driver.dat"), StringComparison.Ordinal);
        Assert.Contains("IF slot_type[write_slot] == 17 THEN", src, StringComparison.Ordinal);
        Assert.Contains("ret = EKI_GetReal(\"machina_kuka_server\", \"DT/DR/A/@V13\", slot_v[write_slot, 13])", src, StringComparison.Ordinal);
        Assert.Contains("    CIRC aux, target C_DIS\n", src.ReplaceLineEndings("\n"), StringComparison.Ordinal);
    }

    [Fact]
    public async Task Stream_Arc_EndsWhereTheCompiledProgramEndsOnTheTwin()
    {
        RobotModel model = RobotModels.Get("KR 6 R900 sixx");
        List<(string Name, string Text)> files = Compile(RobotType.KUKA, Program, model);
        Assert.Contains(files, f => f.Text.Contains("CIRC {E6POS: X 475, Y 0, Z 360, A 180, B 0, C 180}, {E6POS: X 400, Y 100, Z 300,", StringComparison.Ordinal));
        using var offline = new KrlTwinController(new KrlTwinOptions { Model = model });
        offline.Load([.. files]);
        Assert.Equal(KrlProgramState.Finished, offline.Run(null, CancellationToken.None));

        await using var controller = await StartKukaAsync();
        (Robot bot, _, _) = await ConnectKukaAsync(controller);
        try
        {
            IssueAll(bot, Program);
            await bot.WaitForCompletionAsync().WaitAsync(Limit);

            Assert.Empty(controller.Errors);
            Assert.Contains(controller.Twin!.Arm.Trace, t => t.Text.StartsWith("CIRC", StringComparison.Ordinal));
            AssertSameEnd(offline.Arm, controller.Twin.Arm);
            Assert.True(controller.Twin.Arm.Tcp.Position.IsSimilar(new Vector(400, 100, 300), 0.01), controller.Twin.Arm.Tcp.ToString());
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

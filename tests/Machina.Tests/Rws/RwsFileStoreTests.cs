using System.Net;
using System.Text;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Rws;

/// <summary>
/// The controller's mass memory is one store for RAPID and Robot Web Services: a file uploaded to <c>/fileservice/$HOME</c> is what
/// <c>Open "HOME:/…"</c> reads, a file a program wrote is what a client downloads, and both live in the folder the twin was given.
/// </summary>
public sealed class RwsFileStoreTests : IAsyncLifetime
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(20);
    private readonly DirectoryInfo _root = Directory.CreateTempSubdirectory("machina-rws-files-");
    private readonly RapidTwinController _twin;
    private readonly RwsTwinServer _rws;
    private readonly HttpClient _http;

    public RwsFileStoreTests()
    {
        _twin = new RapidTwinController(new RapidTwinOptions { HomeDirectory = Path.Combine(_root.FullName, "home") });
        _rws = new RwsTwinServer(_twin);
        _rws.Start();
        _http = RwsTestClient.For(_rws.Port, new CookieContainer(), Limit);
    }

    public Task InitializeAsync() => Task.CompletedTask;

    public async Task DisposeAsync()
    {
        _http.Dispose();
        await _rws.DisposeAsync();
        _root.Delete(recursive: true);
    }

    [Fact]
    public async Task AFileUploadedThroughRws_IsReadByOpenHome_AndAFileTheProgramWrote_IsDownloaded()
    {
        using HttpResponseMessage put = await _http.PutAsync("/fileservice/$HOME/recipes/r1.txt", new StringContent("speed 250\n", Encoding.ASCII));
        Assert.Equal(HttpStatusCode.Created, put.StatusCode);
        Assert.Equal("speed 250\n", File.ReadAllText(Path.Combine(_root.FullName, "home", "recipes", "r1.txt")));

        _twin.Load(("T.mod", """
            MODULE T
              VAR iodev f;
              VAR string line;
              PROC main()
                Open "HOME:/recipes/r1.txt", f \Read;
                line := ReadStr(f);
                Close f;
                TPWrite "read " + line;
                Open "HOME:/result.txt", f \Write;
                Write f, "done " + line;
                Close f;
                Open "TEMP:/scratch.txt", f \Write;
                Write f, "tmp";
                Close f;
              ENDPROC
            ENDMODULE
            """));
        Assert.Equal(RapidProgramState.Finished, _twin.Run());
        Assert.Equal(["read speed 250"], _twin.Pendant.Lines);

        Assert.Equal("done speed 250\n", await _http.GetStringAsync("/fileservice/$HOME/result.txt"));
        Assert.Equal("tmp\n", await _http.GetStringAsync("/fileservice/$TEMP/scratch.txt"));
        Assert.Equal(
            ["$HOME/recipes/r1.txt", "$HOME/result.txt", "$TEMP/scratch.txt"],
            _rws.Files.Keys.Order(StringComparer.Ordinal));
    }

    [Fact]
    public async Task AModuleAProgramWroteToHome_LoadsThroughRws()
    {
        _twin.Load(("W.mod", """
            MODULE W
              VAR iodev f;
              PROC main()
                Open "HOME:/gen.mod", f \Write;
                Write f, "MODULE Gen";
                Write f, "  PROC Hello()";
                Write f, "    TPWrite ""generated"";";
                Write f, "  ENDPROC";
                Write f, "ENDMODULE";
                Close f;
              ENDPROC
            ENDMODULE
            """));
        Assert.Equal(RapidProgramState.Finished, _twin.Run());

        using HttpResponseMessage master = await _http.PostAsync("/rw/mastership?action=request", new FormUrlEncodedContent([]));
        Assert.Equal(HttpStatusCode.NoContent, master.StatusCode);
        using HttpResponseMessage load = await _http.PostAsync("/rw/rapid/tasks/T_ROB1?action=loadmod",
            new FormUrlEncodedContent([new("modulepath", "$HOME/gen.mod"), new("replace", "false")]));
        Assert.Equal(HttpStatusCode.NoContent, load.StatusCode);
        Assert.Equal(RapidProgramState.Finished, _twin.Run("Hello"));
        Assert.Contains("generated", _twin.Pendant.Lines);
    }

    [Fact]
    public async Task AFolderOtherThanHomeTempOrRamdisk_IsNotFound()
    {
        using HttpResponseMessage put = await _http.PutAsync("/fileservice/$SYSTEM/x.txt", new StringContent("x"));

        Assert.Equal(HttpStatusCode.NotFound, put.StatusCode);
        Assert.Contains("has $HOME, $TEMP and $RAMDISK", await put.Content.ReadAsStringAsync(), StringComparison.Ordinal);
        Assert.Empty(_rws.Files);
    }
}

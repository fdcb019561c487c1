using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// Dashboard commands as UR's client library (Universal_Robots_Client_Library, <c>dashboard_client_implementation_g5.cpp</c>)
/// sends them and the answers it waits for: <c>commandLoadProgram</c> loads a path and then polls <c>programState</c> until it is
/// "STOPPED" and the file's name (its test <c>load_program_in_subdir_works</c> loads "/ursim/programs/wait_program.urp" on
/// URSim); <c>commandGenerateFlightReport</c> wants "Flight Report generated with id:…" and <c>commandGenerateSupportFile</c>
/// "Completed successfully:…" (software 3.13 / 5.8 on). The twin answered the path in full and refused both reports.
/// </summary>
public class UrSimDashboardClientLibraryTests
{
    [Fact]
    public async Task LoadAPath_ProgramStateNamesTheFileOnly_GetLoadedProgramThePath()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);

        Assert.Equal("Loading program: /ursim/programs/wait_program.urp", await UrSimDashboardTests.AskAsync(dashboard, "load /ursim/programs/wait_program.urp"));
        Assert.Equal("STOPPED wait_program.urp", await UrSimDashboardTests.AskAsync(dashboard, "programState"));
        Assert.Equal("Loaded program: /ursim/programs/wait_program.urp", await UrSimDashboardTests.AskAsync(dashboard, "get loaded program"));
        Assert.Equal("Starting program", await UrSimDashboardTests.AskAsync(dashboard, "play"));
        Assert.Equal("PLAYING wait_program.urp", await UrSimDashboardTests.AskAsync(dashboard, "programState"));
        Assert.Equal("Stopped", await UrSimDashboardTests.AskAsync(dashboard, "stop"));
    }

    [Fact]
    public async Task FlightReportAndSupportFile_AnsweredAsTheClientLibraryWaitsForThem()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await UrSimDashboardTests.DashboardAsync(controller.DashboardPort);

        Assert.Equal("Flight Report generated with id: 1", await UrSimDashboardTests.AskAsync(dashboard, "generate flight report"));
        Assert.Equal("Flight Report generated with id: 2", await UrSimDashboardTests.AskAsync(dashboard, "generate flight report controller"));
        Assert.Equal("Completed successfully: .", await UrSimDashboardTests.AskAsync(dashboard, "generate support file ."));
        Assert.Equal("Robotmode: RUNNING", await UrSimDashboardTests.AskAsync(dashboard, "robotmode")); // the connection goes on
    }
}

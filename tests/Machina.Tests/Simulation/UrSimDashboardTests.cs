using System.Net.Sockets;
using System.Text;
using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual UR's dashboard server with a controller state behind it: each answer worded as UR's e-Series dashboard server
/// words it, in the order a client such as UR's client library sends the commands.
/// </summary>
public class UrSimDashboardTests
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);

    [Fact]
    public async Task Dashboard_PowerBrakesLoadPlayPauseStop_AnsweredAsTheManualWordsThem()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, ControllerVersion = new Version(5, 11, 3, 1234) });
        await controller.StartAsync();
        using var dashboard = await DashboardAsync(controller.DashboardPort);

        (string Command, string Answer)[] talk =
        [
            ("robotmode", "Robotmode: RUNNING"),
            ("power off", "Powering off"),
            ("robotmode", "Robotmode: POWER_OFF"),
            ("play", "Failed to execute: play"),
            ("power on", "Powering on"),
            ("robotmode", "Robotmode: IDLE"),
            ("brake release", "Brake releasing"),
            ("robotmode", "Robotmode: RUNNING"),
            ("get loaded program", "No program loaded"),
            ("play", "Failed to execute: play"),
            ("load wait_program", "File not found: wait_program"),
            ("load wait_program.urp", "Loading program: wait_program.urp"),
            ("get loaded program", "Loaded program: wait_program.urp"),
            ("programState", "STOPPED wait_program.urp"),
            ("play", "Starting program"),
            ("programState", "PLAYING wait_program.urp"),
            ("running", "Program running: true"),
            ("pause", "Pausing program"),
            ("programState", "PAUSED wait_program.urp"),
            ("play", "Starting program"),
            ("stop", "Stopped"),
            ("programState", "STOPPED wait_program.urp"),
            ("running", "Program running: false"),
            ("isProgramSaved", "true wait_program.urp"),
            ("safetystatus", "Safetystatus: NORMAL"),
            ("safetymode", "Safetymode: NORMAL"),
            ("is in remote control", "true"),
            ("get operational mode", "NONE"),
            ("set operational mode manual", "Operational mode MANUAL is set"),
            ("get operational mode", "MANUAL"),
            ("get serial number", "20245500001"),
            ("get robot model", "UR5"),
            ("PolyscopeVersion", "URSoftware 5.11.3.1234 (virtual controller)"),
            ("version", "5.11.3.1234"),
            ("popup hello there", "showing popup"),
            ("close popup", "closing popup"),
            ("addToLog a line", "Added log message"),
            ("addToLog", "No log message to add"),
            ("close safety popup", "closing safety popup"),
            ("unlock protective stop", "Protective stop releasing"),
            ("load installation default.installation", "Loading installation: default.installation"),
            ("saveLog", "Log saved to disk"),
            ("restart safety", "Restarting safety"),
            ("robotmode", "Robotmode: POWER_OFF"),
            ("fly", "could not understand: 'fly'"),
            ("shutdown", "Shutting down"),
            ("quit", "Disconnected"),
        ];
        Assert.Equal(talk.Select(t => t.Answer), await AskAllAsync(dashboard, talk));
        Assert.Equal(["a line"], controller.UserLog);
        Assert.Null(controller.Popup);
        Assert.Equal("wait_program.urp", controller.LoadedProgram);
    }

    [Fact]
    public async Task Dashboard_ProtectiveStop_PlayRefusedUntilUnlocked()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await DashboardAsync(controller.DashboardPort);
        Assert.Equal("Loading program: p.urp", await AskAsync(dashboard, "load p.urp"));
        Assert.Equal("Starting program", await AskAsync(dashboard, "play"));
        Assert.True(controller.ProtectiveStop());

        Assert.Equal("Safetystatus: PROTECTIVE_STOP", await AskAsync(dashboard, "safetystatus"));
        Assert.Equal("Failed to execute: play", await AskAsync(dashboard, "play"));
        Assert.Equal("Protective stop releasing", await AskAsync(dashboard, "unlock protective stop"));
        Assert.Equal("Starting program", await AskAsync(dashboard, "play"));
        Assert.Equal("PLAYING p.urp", await AskAsync(dashboard, "programState"));
    }

    [Fact]
    public async Task StartsPoweredOff_AsUrSim_RefusesProgramsUntilPowerOnAndBrakeRelease()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, StartsPoweredOff = true });
        await controller.StartAsync();
        using var dashboard = await DashboardAsync(controller.DashboardPort);
        using var upload = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        const string Program = "def p():\n  write_output_integer_register(3, 11)\nend\n";
        double Register() => controller.Twin.Io.GetNumber(Machina.Simulation.UrScript.UrIoBanks.OutputIntRegisters, 3);

        Assert.Equal(3, controller.RobotMode);
        Assert.Equal("Robotmode: POWER_OFF", await AskAsync(dashboard, "robotmode"));
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(Program));
        await OnlineWait.UntilAsync(() => controller.Errors.Count == 1, "the program to be refused");
        Assert.Equal("Program refused: the robot is POWER_OFF: power it on and release the brakes (dashboard \"power on\", \"brake release\") before a program runs", controller.Errors[0]);

        Assert.Equal("Powering on", await AskAsync(dashboard, "power on"));
        Assert.Equal("Robotmode: IDLE", await AskAsync(dashboard, "robotmode"));
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(Program));
        await OnlineWait.UntilAsync(() => controller.Errors.Count == 2, "the program to be refused again");
        Assert.StartsWith("Program refused: the robot is IDLE: ", controller.Errors[1], StringComparison.Ordinal);
        Assert.Equal(0, Register());
        Assert.False(controller.IsProgramRunning);

        Assert.Equal("Brake releasing", await AskAsync(dashboard, "brake release"));
        Assert.Equal("Robotmode: RUNNING", await AskAsync(dashboard, "robotmode"));
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes(Program));
        await OnlineWait.UntilAsync(() => Register() == 11, "the program to run");
        Assert.Equal(2, controller.Errors.Count);
        Assert.Equal(3, controller.ScriptsReceived);
    }

    [Fact]
    public async Task Load_AfterAScriptRan_ProgramStateNamesTheLoadedProgram()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var dashboard = await DashboardAsync(controller.DashboardPort);
        using var upload = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await upload.GetStream().WriteAsync(Encoding.ASCII.GetBytes("def external():\n  textmsg(\"ran\")\nend\n"));
        await OnlineWait.UntilAsync(() => controller.Twin.ProgramsStarted == 1 && !controller.IsProgramRunning, "the script to end");
        Assert.Equal("STOPPED external", await AskAsync(dashboard, "programState"));

        Assert.Equal("Loading program: wait_program.urp", await AskAsync(dashboard, "load wait_program.urp"));
        Assert.Equal("STOPPED wait_program.urp", await AskAsync(dashboard, "programState"));
    }

    [Fact]
    public async Task UserRole_OnACbSeriesArm_SetAndGotAsItsDashboardWordsThem_AndUnknownOnAnESeries()
    {
        await using var cb = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, Model = RobotModels.Get("UR5") });
        await cb.StartAsync();
        using (var dashboard = await DashboardAsync(cb.DashboardPort))
        {
            (string Command, string Answer)[] talk =
            [
                ("getUserRole", "NONE"),
                ("setUserRole PROGRAMMER", "Setting user role: PROGRAMMER"),
                ("getUserRole", "PROGRAMMER"),
                ("setUserRole operator", "Setting user role: operator"),
                ("getUserRole", "OPERATOR"),
                ("setUserRole admin", "Failed setting user role: admin"),
                ("getUserRole", "OPERATOR"),
                ("setUserRole", "Setting user role: none"),
                ("getUserRole", "NONE"),
                ("setUserRole restricted", "Setting user role: restricted"),
                ("setuserrole LOCKED", "Setting user role: LOCKED"),
                ("getUserRole", "LOCKED"),
                ("setUserRoles", "could not understand: 'setUserRoles'"),
            ];
            Assert.Equal(talk.Select(t => t.Answer), await AskAllAsync(dashboard, talk));
        }
        Assert.Equal("LOCKED", cb.UserRole);

        await using var e = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await e.StartAsync();
        using var eDashboard = await DashboardAsync(e.DashboardPort);
        Assert.Equal("could not understand: 'setUserRole programmer'", await AskAsync(eDashboard, "setUserRole programmer"));
        Assert.Equal("could not understand: 'getUserRole'", await AskAsync(eDashboard, "getUserRole"));
        Assert.Equal("NONE", e.UserRole);
    }

    internal static async Task<DashboardLine> DashboardAsync(int port)
    {
        var client = new TcpClient();
        await client.ConnectAsync("127.0.0.1", port).WaitAsync(Timeout);
        var reader = new StreamReader(client.GetStream(), Encoding.ASCII);
        Assert.Equal("Connected: Universal Robots Dashboard Server", await reader.ReadLineAsync().WaitAsync(Timeout));
        return new DashboardLine(client, reader);
    }

    internal sealed record DashboardLine(TcpClient Client, StreamReader Reader) : IDisposable
    {
        public void Dispose()
        {
            Reader.Dispose();
            Client.Dispose();
        }
    }

    /// <summary>The answers to each command of a conversation, in order.</summary>
    private static async Task<List<string>> AskAllAsync(DashboardLine dashboard, (string Command, string Answer)[] talk)
    {
        var answers = new List<string>();
        foreach ((string command, _) in talk)
        {
            answers.Add(await AskAsync(dashboard, command));
        }
        return answers;
    }

    internal static async Task<string> AskAsync(DashboardLine dashboard, string command)
    {
        await dashboard.Client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(command + "\n"));
        return await dashboard.Reader.ReadLineAsync().WaitAsync(Timeout) ?? "(closed)";
    }
}

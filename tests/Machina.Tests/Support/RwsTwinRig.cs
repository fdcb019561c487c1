using System.Net;
using Machina.Simulation;
using Machina.Simulation.Rapid;
using Machina.Simulation.Rws;

namespace Machina.Tests.Support;

/// <summary>
/// A RAPID twin (IRB 1600) with its motion task, the driver's and monitor's ports reserved on loopback, and Robot Web Services in
/// front of it, as a controller on which the driver is installed through RWS. Dispose it at the end of the test.
/// </summary>
internal sealed class RwsTwinRig : IAsyncDisposable
{
    /// <summary>The monitor task the user configures in the system parameters (docs/rws.md).</summary>
    public const string MonitorTask = "T_MACHINA_MONITOR";

    /// <summary>Starts the rig; <paramref name="withMonitorTask"/> adds the monitor task beside the motion task.</summary>
    public RwsTwinRig(bool withMonitorTask)
    {
        (System.Net.Sockets.TcpListener driver, System.Net.Sockets.TcpListener monitor) = LoopbackPorts.BindPair();
        Port = ((IPEndPoint)driver.LocalEndpoint).Port;
        Twin = new RapidTwinController(new RapidTwinOptions { Model = RobotModels.Get("IRB 1600-8/1.45") });
        Twin.Task(); // the controller's motion task
        if (withMonitorTask)
        {
            Twin.Task(MonitorTask);
        }
        Twin.Reserve(driver);
        Twin.Reserve(monitor);
        Rws = new RwsTwinServer(Twin);
        Rws.Start();
    }

    /// <summary>The controller.</summary>
    public RapidTwinController Twin { get; }

    /// <summary>Its Robot Web Services.</summary>
    public RwsTwinServer Rws { get; }

    /// <summary>The port the driver listens on once installed (the monitor's is the next one).</summary>
    public int Port { get; }

    /// <summary>Stops RWS, then the RAPID tasks (and fails the test if they do not stop).</summary>
    public async ValueTask DisposeAsync()
    {
        await Rws.DisposeAsync();
        Assert.True(Twin.StopTasks(TimeSpan.FromSeconds(10)), "the RAPID tasks to stop");
    }
}

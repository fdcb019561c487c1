using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The RTDE outputs of later software that UR's client library asks for in its exhaustive recipe (session 36): each has the
/// type the client library's fake server gives it, and a value the twin can stand behind (its I/O, gravity and clock; zeros for
/// the dynamics it does not model).
/// </summary>
public class VirtualUrRtdeLaterOutputsTests
{
    private static readonly string[] Names =
    [
        "timestamp", "actual_current_as_torque", "actual_TCP_acceleration", "target_TCP_acceleration",
        "actual_configurable_digital_input_bits", "actual_configurable_digital_output_bits", "target_execution_time",
        "actual_robot_energy_consumed", "actual_robot_braking_energy_dissipated", "encoder0_raw", "encoder1_raw",
        "wrench_calc_from_currents", "target_gravity", "target_base_acceleration", "control_step", "target_base_wrench",
    ];

    [Fact]
    public async Task Rtde_LaterOutputs_AreFoundTypedAndServed()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        controller.Twin.Io.SetBit(UrIoBanks.ConfigurableIn, 2, true);
        controller.Twin.Io.SetBit(UrIoBanks.ConfigurableOut, 5, true);
        controller.Twin.Io.SetBit(UrIoBanks.StandardOut, 1, true); // a standard output is not a configurable one
        controller.Twin.Modes.Gravity = [0, 9.82, 0]; // as set_gravity on a wall-mounted arm
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());

        string[] types = await client.SetupOutputsAsync(125, Names);

        Assert.Equal(
            ["DOUBLE", "VECTOR6D", "VECTOR6D", "VECTOR6D", "UINT64", "UINT64", "DOUBLE", "DOUBLE", "DOUBLE", "INT32", "INT32",
             "VECTOR6D", "VECTOR3D", "VECTOR6D", "UINT64", "VECTOR6D"],
            types);
        Assert.True(await client.StartAsync());
        var data = await client.ReadDataAsync();
        Assert.Equal(1L << 2, (long)data["actual_configurable_digital_input_bits"]);
        Assert.Equal(1L << 5, (long)data["actual_configurable_digital_output_bits"]);
        Assert.Equal([0, 9.82, 0], (double[])data["target_gravity"]);
        Assert.Equal(0.002, (double)data["target_execution_time"]);
        Assert.Equal(Math.Round((double)data["timestamp"] * 500), (long)data["control_step"]);
        foreach (string zero in new[] { "actual_current_as_torque", "actual_TCP_acceleration", "target_TCP_acceleration", "wrench_calc_from_currents", "target_base_acceleration", "target_base_wrench" })
        {
            Assert.Equal(new double[6], (double[])data[zero]);
        }
        Assert.Equal((0.0, 0.0, 0L, 0L), ((double)data["actual_robot_energy_consumed"], (double)data["actual_robot_braking_energy_dissipated"], (long)data["encoder0_raw"], (long)data["encoder1_raw"]));
    }
}

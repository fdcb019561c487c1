using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;
using Machina.Simulation.UrScript;
using Machina.Tests.Support;

namespace Machina.Tests.Simulation;

/// <summary>
/// The virtual UR's RTDE as UR's client libraries use it: the guide's outputs (status bits, analog inputs, TCP offset…), recipes
/// with a trailing comma, and inputs (registers a running program reads, outputs under masks, the speed slider).
/// </summary>
public class UrSimRtdeTests
{
    [Fact]
    public async Task Outputs_TheGuidesStandardOutputs_HaveTheirTypesAndValues()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        controller.SetDigitalInput(3, true);
        controller.SetAnalogInput(1, 4.5);
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());

        string[] names = ["actual_TCP_force", "actual_digital_input_bits", "robot_status_bits", "safety_status_bits", "tcp_offset",
            "standard_analog_input0", "standard_analog_input1", "input_int_register_24", "output_double_register_3", "output_bit_register_64",
            "speed_scaling", "joint_temperatures"];
        string[] types = await client.SetupOutputsAsync(125, names);
        Assert.Equal(["VECTOR6D", "UINT64", "UINT32", "UINT32", "VECTOR6D", "DOUBLE", "DOUBLE", "INT32", "DOUBLE", "BOOL", "DOUBLE", "VECTOR6D"], types);
        Assert.True(await client.StartAsync());
        var data = await client.ReadDataAsync();

        Assert.Equal(new double[6], (double[])data["actual_TCP_force"]);
        Assert.Equal(1L << 3, (long)data["actual_digital_input_bits"]);
        Assert.Equal(1L, (long)data["robot_status_bits"]); // powered, no program running
        Assert.Equal(1L, (long)data["safety_status_bits"]); // normal
        Assert.Equal(new double[6], (double[])data["tcp_offset"]);
        Assert.Equal((0.0, 4.5), ((double)data["standard_analog_input0"], (double)data["standard_analog_input1"]));
        Assert.Equal(1.0, (double)data["speed_scaling"]);
    }

    [Fact]
    public async Task Outputs_RecipeWithATrailingComma_HasNoExtraName()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());

        Assert.Equal(["DOUBLE", "VECTOR6D"], await client.SetupOutputsTextAsync(125, "timestamp,actual_q,"));
        Assert.True(await client.StartAsync());
        Assert.Equal(-Math.PI / 2, ((double[])(await client.ReadDataAsync())["actual_q"])[1], 12);
    }

    [Fact]
    public async Task Inputs_RecipeIdsCountFromOneApartFromOutputs_AsUrRtdeSendsThem()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupOutputsAsync(125, "timestamp");
        Assert.Equal(1, client.RecipeId);
        var (first, _) = await client.SetupInputsAsync("input_int_register_0", "input_double_register_0");
        var (second, _) = await client.SetupInputsAsync("input_int_register_0");
        Assert.Equal((1, 2), (first, second));
        Assert.True(await client.StartAsync());

        // ur_rtde's "no command" package: recipe 2, one int.
        await client.SendInputsAsync(second, [0, 0, 0, 5]);
        await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(UrIoBanks.InputIntRegisters, 0) == 5, "the input to arrive");
        Assert.Empty(controller.Errors);
    }

    [Fact]
    public async Task Inputs_RegistersReachTheRunningProgram_AndMasksSetOutputs()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        var (id, types) = await client.SetupInputsAsync("input_int_register_24", "input_double_register_2", "standard_digital_output_mask", "standard_digital_output");
        Assert.Equal(["INT32", "DOUBLE", "UINT8", "UINT8"], types);
        Assert.NotEqual(0, id);
        Assert.True(await client.StartAsync());

        // A program copies the registers it reads to the output registers, as a client's control script does.
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def copy():\n  while True:\n    write_output_integer_register(25, read_input_integer_register(24))\n" +
            "    write_output_float_register(5, read_input_float_register(2))\n    sync()\n  end\nend\n"));
        var values = new byte[4 + 8 + 1 + 1];
        BinaryPrimitives.WriteInt32BigEndian(values, -4321);
        BinaryPrimitives.WriteDoubleBigEndian(values.AsSpan(4), 2.25);
        values[12] = 0b1010_0000; // outputs 5 and 7 change…
        values[13] = 0b1000_0001; // …7 to on, 5 to off; 0 stays off (not in the mask)
        await client.SendInputsAsync(id, values);

        await OnlineWait.UntilAsync(() => controller.Twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 25) == -4321
            && controller.Twin.Io.GetNumber(UrIoBanks.OutputFloatRegisters, 5) == 2.25, "the program to copy the input registers");
        Assert.Equal([false, false, false, false, false, false, false, true],
            Enumerable.Range(0, 8).Select(i => controller.Twin.Io.GetBit(UrIoBanks.StandardOut, i)));
    }

    [Fact]
    public async Task Inputs_HeldByAnotherClient_AreInUse_AndFreedWhenItCloses()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        var first = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        using var second = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await first.NegotiateAsync());
        Assert.True(await second.NegotiateAsync());

        Assert.Equal(["UINT32", "DOUBLE"], (await first.SetupInputsAsync("speed_slider_mask", "speed_slider_fraction")).Types);
        var refused = await second.SetupInputsAsync("speed_slider_mask", "input_int_register_30", "no_such_input");
        Assert.Equal(0, refused.Id);
        Assert.Equal(["IN_USE", "INT32", "NOT_FOUND"], refused.Types);

        first.Dispose();
        await OnlineWait.UntilAsync(() => second.SetupInputsAsync("speed_slider_mask").GetAwaiter().GetResult().Id != 0, "the first client's inputs to be freed");
    }

    [Fact]
    public async Task Inputs_SpeedSlider_ScalesWhatRtdeReports()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        var (id, _) = await client.SetupInputsAsync("speed_slider_mask", "speed_slider_fraction");
        await client.SetupOutputsAsync(125, "target_speed_fraction");
        Assert.True(await client.StartAsync());
        var values = new byte[12];
        BinaryPrimitives.WriteUInt32BigEndian(values, 1);
        BinaryPrimitives.WriteDoubleBigEndian(values.AsSpan(4), 0.3);
        await client.SendInputsAsync(id, values);

        await OnlineWait.UntilAsync(() => controller.SpeedSlider == 0.3, "the slider");
        double reported = 0;
        await OnlineWait.UntilAsync(() => (reported = (double)client.ReadDataAsync().GetAwaiter().GetResult()["target_speed_fraction"]) == 0.3, "RTDE to report it");
        Assert.Equal(0.3, reported);
    }
}

using System.Buffers.Binary;
using System.Diagnostics;
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
    public async Task Outputs_Timestamp_CountsFromTheControllersStart()
    {
        long made = Stopwatch.GetTimestamp();
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = await StartedAsync(controller, 125, "timestamp");

        // "Time elapsed since the controller was started" (UR's record.py writes it in its first column), not the computer's.
        double timestamp = (double)(await client.ReadDataAsync())["timestamp"];
        Assert.InRange(timestamp, 0, Stopwatch.GetElapsedTime(made).TotalSeconds);
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

    [Fact]
    public async Task Version_OfACbSeriesArm_IsTheSoftwareEveryInterfaceReports_AndItsRateAtMost125Hz()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true, Model = RobotModels.Get("UR5") });
        await controller.StartAsync();
        using var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());

        Assert.Equal(new uint[] { 3, 15, 8, 0 }, await client.ControllerVersionAsync());
        Assert.Equal(["DOUBLE"], await client.SetupOutputsAsync(500, "timestamp"));
        Assert.Equal(0, client.RecipeId);
        Assert.Equal("RTDE: refused an output frequency of 500 Hz (1 to 125).", Assert.Single(controller.Errors));
        Assert.Equal(["DOUBLE"], await client.SetupOutputsAsync(125, "timestamp"));
        Assert.Equal(1, client.RecipeId);
    }

    [Fact]
    public async Task Outputs_ARecipeTooLongToFrame_IsRefused_AndOtherClientsKeepTheirData()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var other = await StartedAsync(controller, 125, "timestamp");
        using var greedy = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await greedy.NegotiateAsync());

        // 1,366 joint vectors of 48 bytes: a data package of 65,572 bytes, past the 65,535 its size field holds.
        string[] types = await greedy.SetupOutputsAsync(125, [.. Enumerable.Repeat("actual_q", 1366)]);
        Assert.Equal(1366, types.Length);
        Assert.Equal(0, greedy.RecipeId);
        Assert.Equal("RTDE: refused an output recipe whose data package would be 65572 bytes (at most 65535).", Assert.Single(controller.Errors));
        Assert.False(await greedy.StartAsync());

        Assert.True(await ReadUntilAsync(other, 0.1) >= 0.1);
    }

    [Fact]
    public async Task Outputs_AClientThatStopsReading_IsDropped_AndOtherClientsKeepTheirData()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var reading = await StartedAsync(controller, 125, "timestamp");
        using var stalled = new TcpClient();
        await stalled.ConnectAsync("127.0.0.1", controller.RtdePort);
        NetworkStream stalledStream = stalled.GetStream();
        using (var setup = GuideRtdeClient.Attach(stalledStream))
        {
            Assert.True(await setup.NegotiateAsync());
            await setup.SetupOutputsAsync(500, [.. Enumerable.Repeat("actual_q", 1300)]); // 62 kB a package, 31 MB/s
            Assert.True(await setup.StartAsync());
        }

        // The stalled client fills its socket's buffers within a second and is dropped 2 s later; the other reads on meanwhile.
        Assert.True(await ReadUntilAsync(reading, 5) >= 5);
        var buffer = new byte[1 << 16];
        using var drained = new CancellationTokenSource(TimeSpan.FromSeconds(15));
        try
        {
            while (await stalledStream.ReadAsync(buffer, drained.Token) > 0)
            {
            }
        }
        catch (IOException)
        {
            // reset rather than closed: the twin ended the connection either way (a cancelled read, instead, fails the test)
        }
    }

    [Fact]
    public async Task Outputs_JointAndToolSpeeds_AreThoseOfTheMotionInProgress()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions());
        await controller.StartAsync();
        using var client = await StartedAsync(controller, 125, "actual_qd", "target_qd", "actual_TCP_speed", "target_TCP_speed", "actual_TCP_pose");
        Assert.Equal(new double[6], (double[])(await client.ReadDataAsync())["actual_qd"]);

        // The base turns 0.6 rad at 0.4 rad/s (ramps of 0.08 s): about 1.4 s of cruise, the tool on a circle round the base.
        using var script = await UrSimClientInterfaceTests.ConnectAsync(controller.Port);
        await script.GetStream().WriteAsync(Encoding.ASCII.GetBytes(
            "def turn():\n  movej([0.6, -1.5707963, -1.5707963, -1.5707963, 1.5707963, 0], a=5, v=0.4)\nend\n"));
        Dictionary<string, object> data;
        int packages = 0;
        do
        {
            data = await client.ReadDataAsync();
            Assert.True(++packages < 125 * 15, "the base never turned at 0.4 rad/s");
        }
        // On the cruise: a sample across a ramp's end reads a little less (0.399997) and is not yet the cruise's speed.
        while (Math.Round(((double[])data["actual_qd"])[0], 6) < 0.4);

        double[] qd = (double[])data["actual_qd"], tcp = (double[])data["actual_TCP_pose"], speed = (double[])data["actual_TCP_speed"];
        Assert.Equal(new double[] { 0.4, 0, 0, 0, 0, 0 }, qd.Select(v => Math.Round(v, 6)));
        Assert.Equal(qd, (double[])data["target_qd"]);
        Assert.Equal(speed, (double[])data["target_TCP_speed"]);
        Assert.Equal(0.4 * Math.Sqrt(tcp[0] * tcp[0] + tcp[1] * tcp[1]), Math.Sqrt(speed[0] * speed[0] + speed[1] * speed[1]), 3);
        Assert.Equal(new double[] { 0, 0, 0, 0.4 }, new[] { speed[2], speed[3], speed[4], speed[5] }.Select(v => Math.Round(v, 3)));
    }

    /// <summary>A client of the controller's RTDE that has set up these outputs and started.</summary>
    private static async Task<GuideRtdeClient> StartedAsync(VirtualUrController controller, double frequency, params string[] names)
    {
        var client = await GuideRtdeClient.ConnectAsync(controller.RtdePort);
        Assert.True(await client.NegotiateAsync());
        await client.SetupOutputsAsync(frequency, names);
        Assert.True(await client.StartAsync());
        return client;
    }

    /// <summary>Reads a client's packages of 'timestamp' until <paramref name="seconds"/> of controller time have gone by; the last span seen.</summary>
    private static async Task<double> ReadUntilAsync(GuideRtdeClient client, double seconds)
    {
        double first = (double)(await client.ReadDataAsync())["timestamp"];
        double span = 0;
        while (span < seconds)
        {
            span = (double)(await client.ReadDataAsync())["timestamp"] - first;
        }
        return span;
    }

    [Fact]
    public async Task Framing_RequestsArrivingByteByByte_AreAnsweredAsWhole()
    {
        await using var controller = new VirtualUrController(new VirtualUrControllerOptions { InstantExecution = true });
        await controller.StartAsync();
        using var client = new TcpClient { NoDelay = true };
        await client.ConnectAsync("127.0.0.1", controller.RtdePort);
        NetworkStream stream = client.GetStream();
        byte[] setup = [0, 5, 86, 0, 2, 0, 3, 118];
        foreach (byte b in setup)
        {
            await stream.WriteAsync(new[] { b });
            await stream.FlushAsync();
            await Task.Delay(2);
        }

        var answers = new byte[4 + 19];
        await stream.ReadExactlyAsync(answers).AsTask().WaitAsync(TimeSpan.FromSeconds(15));
        Assert.Equal(new byte[] { 0, 4, 86, 1, 0, 19, 118, 0, 0, 0, 5, 0, 0, 0, 11, 0, 0, 0, 0, 0, 0, 0, 0 }, answers);
        Assert.Empty(controller.Errors);
    }
}

using System.Net;
using System.Net.Sockets;
using System.Text;
using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>
/// The original Machina.NET host's bytes, sent over a bare socket to the virtual ABB running the unchanged drivers/abb modules
/// on its RAPID interpreter (issue 22: "the original Machina.NET host keeps streaming to it"). The requests are written as the
/// original host encodes them (/work/shared/spec/online.md §6.2 Framing, §6.3 Instruction codes and their example messages,
/// §6.6 Host-side translation); the replies are compared byte for byte with §6.2 (acknowledgements), §6.4 (data responses)
/// and §6.5 (handshake), and the twin's arm must stand where each motion put it.
/// </summary>
public class VirtualAbbOriginalHostTests
{
    // Generous for a loaded 2-core CI machine: every read waits for text the driver must send, never for its absence.
    private static readonly TimeSpan Limit = TimeSpan.FromMinutes(2);

    [Fact]
    public async Task OriginalHostBytes_Spec6_DriverRepliesExactlyAndTheArmReachesEveryPose()
    {
        // The original host expects driver 1.4.x (§6.1): its handshake is $20..$23, without the $25 of 1.6.
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            InstantExecution = true,
            Model = RobotModels.Get("IRB 1600-8/1.45"),
            DriverVersion = new Version(1, 4, 2),
        });
        await controller.StartAsync();
        using var driver = await ConnectAsync(controller.Port);

        // §6.5 step 2: version, flange pose (tool0, wobj0; mm 3 decimals, quaternion 4), joints (3 decimals), external axes.
        Assert.Equal("$20 1 4 2;$21 750 0 1121.5 0 0 1 0;$22 0 0 0 0 90 0;$23 9E9 9E9 9E9 9E9 9E9 9E9;", await ReadMessagesAsync(driver, 4));

        // §6.5 step 4, §6.4 code 24: the monitor on port + 1 reports in three chunks joined by '>' (19 values).
        using (var monitor = await ConnectAsync(controller.MonitorPort))
        {
            Assert.Equal("$24 750 0 1121.5 0 0 1 0>0 0 0 0 90 0>9E9 9E9 9E9 9E9 9E9 9E9;", await ReadMessagesAsync(monitor, 1));
        }

        // §6.3 codes 4 (speed, unrounded), 5 (precision), 1 (MoveL: absolute position and quaternion W X Y Z); §6.2: a request
        // may be split across reads, so the MoveL arrives in two writes.
        await SendAsync(driver, "@1 4 100;@2 5 2;@3 1 400 0 5");
        await SendAsync(driver, "00 0 0 1 0;");
        Assert.Equal("@1 4;@2 5;@3 1;", await ReadMessagesAsync(driver, 3));
        AssertPose(controller.State, new Vector(400, 0, 500), Rotation.FromQuaternion(0, 0, 1, 0));

        // §6.3 code 3 (MoveAbsJ, degrees).
        await SendAsync(driver, "@4 3 0 0 0 0 90 0;");
        Assert.Equal("@4 3;", await ReadMessagesAsync(driver, 1));
        Assert.True(controller.State.Joints.IsSimilar(new Joints(0, 0, 0, 0, 90, 0), 1e-6), $"joints {controller.State.Joints}");

        // §6.3 code 7 (message), 10 (digital output by name), 11 (analog output, sent twice with one id: §6.6, BUG-A3), 6 (wait, s).
        await SendAsync(driver, "@5 7 \"Hello world!\";@6 10 \"DO_15\" 1;@7 11 \"AO_1\" 0.5;@7 11 \"AO_1\" 0.5;@8 6 0.05;");
        Assert.Equal("@5 7;@6 10;@7 11;@7 11;@8 6;", await ReadMessagesAsync(driver, 5));
        Assert.Contains("Hello world!", controller.PendantMessages);
        Assert.True(controller.State.DigitalOutputs.GetValueOrDefault("DO_15"), "DO_15 is set");
        Assert.Equal(0.5, controller.State.AnalogOutputs.GetValueOrDefault("AO_1"), 6);

        // §6.3 code 8 (attach tool: X Y Z QW QX QY QZ KG CX CY CZ), then code 2 (MoveJ) with the tool: the TCP reaches the target.
        await SendAsync(driver, "@9 8 0 0 100 1 0 0 0 1 0 0 50;@10 2 300 100 600 0 0 1 0;");
        Assert.Equal("@9 8;@10 2;", await ReadMessagesAsync(driver, 2));
        AssertPose(controller.State, new Vector(300, 100, 600), Rotation.FromQuaternion(0, 0, 1, 0));
        Assert.True(controller.State.Tool is { } tool && tool.Position.IsSimilar(new Vector(0, 0, 100), 1e-6), $"tool {controller.State.Tool}");

        // §6.6 ExternalAxis target All: "@0 15 …" (id 0: acknowledged "15;" without '@', §6.2) then "@id 16 …"; then code 9 (detach
        // tool): the reported TCP is the flange again, 100 mm above the point the tool reached (the tool points down).
        await SendAsync(driver, "@0 15 9E9 9E9 9E9 9E9 9E9 9E9;@11 16 9E9 9E9 9E9 9E9 9E9 9E9;@12 9;");
        Assert.Equal("15;@11 16;@12 9;", await ReadMessagesAsync(driver, 3));
        AssertPose(controller.State, new Vector(300, 100, 700), Rotation.FromQuaternion(0, 0, 1, 0));
        Assert.Null(controller.State.Tool);

        Assert.Equal([1, 2, 3, 4, 5, 6, 7, 7, 8, 9, 10, 11, 12], controller.ExecutedIds); // the id-0 request runs but has no id to count
        Assert.Empty(controller.Errors);
    }

    private static void AssertPose(VirtualAbbState state, Vector position, Rotation rotation)
    {
        Assert.True(state.Position.IsSimilar(position, 1e-3), $"position {state.Position}, expected {position}");
        Assert.True(state.Rotation.IsSimilar(rotation, 1e-3), $"rotation {state.Rotation}, expected {rotation}");
    }

    private static async Task<TcpClient> ConnectAsync(int port)
    {
        var client = new TcpClient { NoDelay = true };
        using var timeout = new CancellationTokenSource(Limit);
        await client.ConnectAsync(IPAddress.Loopback, port, timeout.Token);
        return client;
    }

    /// <summary>Writes ASCII text, as the original host does (§6.1 Encoding).</summary>
    private static async Task SendAsync(TcpClient client, string text)
    {
        using var timeout = new CancellationTokenSource(Limit);
        await client.GetStream().WriteAsync(Encoding.ASCII.GetBytes(text), timeout.Token);
    }

    /// <summary>Reads byte by byte until <paramref name="count"/> messages (each ends with ';') arrived; returns their exact text.</summary>
    private static async Task<string> ReadMessagesAsync(TcpClient client, int count)
    {
        using var timeout = new CancellationTokenSource(Limit);
        var text = new StringBuilder();
        var one = new byte[1];
        while (count > 0)
        {
            if (await client.GetStream().ReadAsync(one, timeout.Token) == 0)
            {
                throw new IOException($"The connection closed after \"{text}\".");
            }
            text.Append((char)one[0]);
            if (one[0] == (byte)';')
            {
                count--;
            }
        }
        return text.ToString();
    }
}

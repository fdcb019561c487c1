using System.Buffers.Binary;
using System.Net;
using System.Net.Sockets;
using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// Machina's URScript driver (drivers/ur, filled as for a robot) runs unchanged on the twin, against a small host written here
/// from docs/protocol-ur.md: big-endian int32 values, 1e-6 m and 1e-6 rad per unit (driver 3.0) (not the library's UrWire).
/// </summary>
public class UrDriverOnTwinTests
{
    private const int ResVersion = -50, ResFullPose = -54, ResEnd = int.MinValue;

    [Fact]
    public async Task Driver_ConnectsSendsVersionAndPose_ExecutesStreamedMoves_AndAcknowledgesThem()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        using var twin = new UrTwinController();
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        try
        {
            twin.Receive(UrDriverScript.For("127.0.0.1", port));
            using TcpClient client = await listener.AcceptTcpClientAsync(timeout.Token);
            NetworkStream stream = client.GetStream();

            Assert.Equal(new[] { ResVersion, 3, 0, 0, ResEnd }, await ReadInts(stream, 5, timeout.Token));
            int[] pose = await ReadInts(stream, 14, timeout.Token);
            Assert.Equal(ResFullPose, pose[0]);
            Assert.Equal(new[] { 0, -1_570_796, 1_570_796, -1_570_796, -1_570_796, 0 }, pose[7..13]);
            Assert.Equal(ResEnd, pose[13]);

            // id 1: movej to joints; id 2: movej to pose p[0.4, -0.1, 0.4, 0, pi, 0]; id 3: standard digital out 2 on.
            await Send(stream, [1, 3, 0, -1_200_000, 1_600_000, -1_970_796, -1_570_796, 0], timeout.Token);
            await Send(stream, [2, 2, 400_000, -100_000, 400_000, 0, 3_141_593, 0], timeout.Token);
            await Send(stream, [3, 13, 2, 1, 0], timeout.Token);
            int[] acks;
            try
            {
                acks = await ReadInts(stream, 3, timeout.Token);
            }
            catch (EndOfStreamException)
            {
                twin.WaitForEnd(TimeSpan.FromSeconds(10));
                throw new Xunit.Sdk.XunitException($"The driver stopped: {twin.Error} | {string.Join(" | ", twin.Pendant.Lines)}");
            }
            Assert.Equal(new[] { 1, 2, 3 }, acks);

            Assert.Equal(3.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 24));
            Assert.Equal(3.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 25));
            Assert.True(twin.Io.GetBit(UrIoBanks.StandardOut, 2));
            Pose tcp = twin.Arm.Tcp;
            Assert.Equal(400, tcp.Position.X, 3);
            Assert.Equal(-100, tcp.Position.Y, 3);
            Assert.Equal(400, tcp.Position.Z, 3);
            Assert.Contains("Machina driver 3.0.0 connected to 127.0.0.1", twin.Pendant.Lines);
            Assert.Equal(UrProgramState.Running, twin.State);
        }
        finally
        {
            twin.StopProgram();
            listener.Stop();
        }
        Assert.Equal(UrProgramState.Stopped, twin.State);
    }

    [Fact]
    public async Task Driver_UnknownInstructionCode_StopsWithItsMessage()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        using var twin = new UrTwinController();
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        try
        {
            twin.Receive(UrDriverScript.For("127.0.0.1", port));
            using TcpClient client = await listener.AcceptTcpClientAsync(timeout.Token);
            NetworkStream stream = client.GetStream();
            await ReadInts(stream, 19, timeout.Token);
            await Send(stream, [7, 99], timeout.Token);
            Assert.True(twin.WaitForEnd(TimeSpan.FromSeconds(20)));
            Assert.Equal(UrProgramState.Finished, twin.State);
            Assert.Equal("Machina: unknown instruction code, stopping: 99", twin.Pendant.Lines[^1]);
            Assert.Equal(7.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 25));
            Assert.Equal(0.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 24));
            // Out of step is the stream's fault, not an instruction's: the instance number (1) negated tells the host so.
            Assert.Equal(-1.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 26));
        }
        finally
        {
            twin.StopProgram();
            listener.Stop();
        }
    }

    /// <summary>
    /// An instruction whose values stop coming after its header (a stalled link): the driver waits its values timeout (filled
    /// in as 0.2 s here), then publishes its instance number negated and halts; nothing of the instruction runs.
    /// </summary>
    [Fact]
    public async Task Driver_ValuesStallAfterTheHeader_HaltsAfterItsTimeout_InstanceNegated_NothingRuns()
    {
        using var listener = new TcpListener(IPAddress.Loopback, 0);
        listener.Start();
        int port = ((IPEndPoint)listener.LocalEndpoint).Port;
        using var twin = new UrTwinController();
        using var timeout = new CancellationTokenSource(TimeSpan.FromSeconds(30));
        try
        {
            twin.Receive(UrDriverScript.For("127.0.0.1", port, 9, TimeSpan.FromMilliseconds(200)));
            using TcpClient client = await listener.AcceptTcpClientAsync(timeout.Token);
            NetworkStream stream = client.GetStream();
            await ReadInts(stream, 19, timeout.Token);
            Assert.Equal(9.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 26));
            Pose before = twin.Arm.Tcp;

            // A move's id, code and two of its six values; the rest never comes (the connection stays open).
            await Send(stream, [5, 1, 400_000, -100_000], timeout.Token);

            Assert.True(twin.WaitForEnd(TimeSpan.FromSeconds(20)));
            Assert.Equal(UrProgramState.Finished, twin.State);
            Assert.Equal("Machina: incomplete instruction, stopping. Expected values: 6", twin.Pendant.Lines[^1]);
            Assert.Equal(-9.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 26));
            Assert.Equal(5.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 25));
            Assert.Equal(0.0, twin.Io.GetNumber(UrIoBanks.OutputIntRegisters, 24));
            Assert.True(twin.Arm.Tcp.Position.IsSimilar(before.Position, 1e-9), twin.Arm.Tcp.Position.ToString());
            Assert.Equal(0, await stream.ReadAsync(new byte[4], timeout.Token)); // closed with the program, never acknowledged
        }
        finally
        {
            twin.StopProgram();
            listener.Stop();
        }
    }

    private static async Task Send(NetworkStream stream, int[] values, CancellationToken cancellation)
    {
        var bytes = new byte[values.Length * 4];
        for (int i = 0; i < values.Length; i++)
        {
            BinaryPrimitives.WriteInt32BigEndian(bytes.AsSpan(4 * i), values[i]);
        }
        await stream.WriteAsync(bytes, cancellation);
    }

    private static async Task<int[]> ReadInts(NetworkStream stream, int count, CancellationToken cancellation)
    {
        var bytes = new byte[count * 4];
        await stream.ReadExactlyAsync(bytes, cancellation);
        return [.. Enumerable.Range(0, count).Select(i => BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(4 * i)))];
    }
}

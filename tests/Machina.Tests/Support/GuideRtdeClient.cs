using System.Buffers.Binary;
using System.Net.Sockets;
using System.Text;

namespace Machina.Tests.Support;

/// <summary>
/// An RTDE client written from Universal Robots' RTDE guide alone, sharing no code with Machina's host or the virtual UR:
/// every package is [uint16 size incl. header][uint8 type][payload], big-endian.
/// </summary>
internal sealed class GuideRtdeClient : IDisposable
{
    private static readonly TimeSpan Timeout = TimeSpan.FromSeconds(15);
    private readonly TcpClient? _client;
    private readonly NetworkStream _stream;
    private string[] _names = [];
    private string[] _types = [];

    private GuideRtdeClient(TcpClient? client, NetworkStream stream)
    {
        _client = client;
        _stream = stream;
    }

    internal byte RecipeId { get; private set; }

    internal static async Task<GuideRtdeClient> ConnectAsync(int port)
    {
        var client = new TcpClient();
        await client.ConnectAsync("127.0.0.1", port).WaitAsync(Timeout);
        return new GuideRtdeClient(client, client.GetStream());
    }

    /// <summary>A client talking over a connection the caller owns (disposing this one leaves it open).</summary>
    internal static GuideRtdeClient Attach(NetworkStream stream) => new(null, stream);

    /// <summary>'V' (86) with protocol version 2 as uint16; the reply's uint8 is 1 when accepted.</summary>
    internal async Task<bool> NegotiateAsync()
    {
        var payload = new byte[2];
        BinaryPrimitives.WriteUInt16BigEndian(payload, 2);
        var (_, reply) = await RequestAsync(86, payload);
        return reply[0] == 1;
    }

    /// <summary>'v' (118): major, minor, bugfix, build as four uint32.</summary>
    internal async Task<uint[]> ControllerVersionAsync()
    {
        var (_, reply) = await RequestAsync(118, []);
        return [.. Enumerable.Range(0, 4).Select(i => BinaryPrimitives.ReadUInt32BigEndian(reply.AsSpan(i * 4)))];
    }

    /// <summary>'O' (79): frequency as a double, then the names joined by commas; the reply is the recipe id and the types.</summary>
    internal async Task<string[]> SetupOutputsAsync(double frequency, params string[] names)
    {
        byte[] text = Encoding.ASCII.GetBytes(string.Join(",", names));
        var payload = new byte[8 + text.Length];
        BinaryPrimitives.WriteDoubleBigEndian(payload, frequency);
        text.CopyTo(payload, 8);
        var (_, reply) = await RequestAsync(79, payload);
        RecipeId = reply[0];
        _names = names;
        _types = Encoding.ASCII.GetString(reply, 1, reply.Length - 1).Split(',');
        return _types;
    }

    /// <summary>'O' (79) with the recipe text as given (e.g. with a trailing comma, as some clients send it); the names are those of the types answered.</summary>
    internal async Task<string[]> SetupOutputsTextAsync(double frequency, string recipe)
    {
        byte[] text = Encoding.ASCII.GetBytes(recipe);
        var payload = new byte[8 + text.Length];
        BinaryPrimitives.WriteDoubleBigEndian(payload, frequency);
        text.CopyTo(payload, 8);
        var (_, reply) = await RequestAsync(79, payload);
        RecipeId = reply[0];
        _types = Encoding.ASCII.GetString(reply, 1, reply.Length - 1).Split(',');
        _names = recipe.Split(',')[.._types.Length];
        return _types;
    }

    /// <summary>'I' (73): the input names joined by commas; the reply is the input recipe id (0 when refused) and the types.</summary>
    internal async Task<(byte Id, string[] Types)> SetupInputsAsync(params string[] names)
    {
        var (_, reply) = await RequestAsync(73, Encoding.ASCII.GetBytes(string.Join(",", names)));
        return (reply[0], Encoding.ASCII.GetString(reply, 1, reply.Length - 1).Split(','));
    }

    /// <summary>'U' (85) from the client: an input recipe's id, then its values as the caller wrote them (big-endian); the controller does not answer.</summary>
    internal async Task SendInputsAsync(byte recipe, byte[] values)
    {
        var package = new byte[4 + values.Length];
        BinaryPrimitives.WriteUInt16BigEndian(package, (ushort)package.Length);
        package[2] = 85;
        package[3] = recipe;
        values.CopyTo(package, 4);
        await _stream.WriteAsync(package);
    }

    /// <summary>'S' (83): start; the reply's uint8 is 1 when accepted.</summary>
    internal async Task<bool> StartAsync()
    {
        var (_, reply) = await RequestAsync(83, []);
        return reply[0] == 1;
    }

    /// <summary>Reads the next 'U' (85) data package: values by name (doubles, or arrays of doubles for vectors, ints as long).</summary>
    internal async Task<Dictionary<string, object>> ReadDataAsync()
    {
        while (true)
        {
            var (type, payload) = await ReadPackageAsync();
            if (type != 85)
            {
                continue;
            }
            Assert.Equal(RecipeId, payload[0]);
            var values = new Dictionary<string, object>();
            int at = 1;
            for (int i = 0; i < _names.Length; i++)
            {
                switch (_types[i])
                {
                    case "VECTOR6D":
                        values[_names[i]] = Enumerable.Range(0, 6).Select(k => BinaryPrimitives.ReadDoubleBigEndian(payload.AsSpan(at + k * 8))).ToArray();
                        at += 48;
                        break;
                    case "VECTOR3D":
                        values[_names[i]] = Enumerable.Range(0, 3).Select(k => BinaryPrimitives.ReadDoubleBigEndian(payload.AsSpan(at + k * 8))).ToArray();
                        at += 24;
                        break;
                    case "DOUBLE":
                        values[_names[i]] = BinaryPrimitives.ReadDoubleBigEndian(payload.AsSpan(at));
                        at += 8;
                        break;
                    case "INT32":
                        values[_names[i]] = (long)BinaryPrimitives.ReadInt32BigEndian(payload.AsSpan(at));
                        at += 4;
                        break;
                    case "UINT32":
                        values[_names[i]] = (long)BinaryPrimitives.ReadUInt32BigEndian(payload.AsSpan(at));
                        at += 4;
                        break;
                    case "UINT64":
                        values[_names[i]] = (long)BinaryPrimitives.ReadUInt64BigEndian(payload.AsSpan(at));
                        at += 8;
                        break;
                    case "BOOL" or "UINT8":
                        values[_names[i]] = (long)payload[at];
                        at += 1;
                        break;
                    default:
                        throw new InvalidOperationException("type not used by these tests: " + _types[i]);
                }
            }
            Assert.Equal(payload.Length, at);
            return values;
        }
    }

    private async Task<(byte Type, byte[] Payload)> RequestAsync(byte type, byte[] payload)
    {
        var package = new byte[3 + payload.Length];
        BinaryPrimitives.WriteUInt16BigEndian(package, (ushort)package.Length);
        package[2] = type;
        payload.CopyTo(package, 3);
        await _stream.WriteAsync(package);
        while (true)
        {
            var reply = await ReadPackageAsync();
            if (reply.Type == type)
            {
                return reply;
            }
        }
    }

    private async Task<(byte Type, byte[] Payload)> ReadPackageAsync()
    {
        var header = new byte[3];
        await _stream.ReadExactlyAsync(header).AsTask().WaitAsync(Timeout);
        int size = BinaryPrimitives.ReadUInt16BigEndian(header);
        var payload = new byte[size - 3];
        await _stream.ReadExactlyAsync(payload).AsTask().WaitAsync(Timeout);
        return (header[2], payload);
    }

    public void Dispose() => _client?.Dispose();
}

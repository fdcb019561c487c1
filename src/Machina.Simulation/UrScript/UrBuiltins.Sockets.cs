using System.Text;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    private const string DefaultSocket = "socket_0";

    private static void AddSockets(Dictionary<string, UrBuiltin> t)
    {
        Add(t, "socket_open", SocketOpen, R("address"), R("port"), O("socket_name", DefaultSocket));
        Add(t, "socket_close", (m, line, a) =>
        {
            string name = Str(a, 0, line, "socket_close", "socket_name");
            if (m.Sockets.Remove(name, out UrSocket? socket))
            {
                socket.Dispose();
            }
            return UrNone.Value;
        }, O("socket_name", DefaultSocket));
        Add(t, "socket_read_binary_integer", (m, line, a) =>
        {
            int count = Int(a, 0, line, "socket_read_binary_integer", "number");
            if (count < 1 || count > 30)
            {
                throw new UrRuntimeException(line, "socket_read_binary_integer: 'number' must be 1 to 30");
            }
            UrSocket socket = Socket(m, line, a, 1, "socket_read_binary_integer");
            double timeout = Num(a, 2, line, "socket_read_binary_integer", "timeout");
            FinishBlendBeforeWaiting(m, line, socket);
            UrList values;
            using (m.Unlock())
            {
                values = socket.ReadIntegers(count, ReadWait(m, timeout), m.Cancellation);
            }
            return WithinStep(m, line, socket, "socket_read_binary_integer", values);
        }, R("number"), O("socket_name", DefaultSocket), O("timeout", 2));
        Add(t, "socket_read_ascii_float", (m, line, a) =>
        {
            int count = Int(a, 0, line, "socket_read_ascii_float", "number");
            if (count < 1 || count > 30)
            {
                throw new UrRuntimeException(line, "socket_read_ascii_float: 'number' must be 1 to 30");
            }
            UrSocket socket = Socket(m, line, a, 1, "socket_read_ascii_float");
            double timeout = Num(a, 2, line, "socket_read_ascii_float", "timeout");
            FinishBlendBeforeWaiting(m, line, socket);
            CancellationToken token = m.Cancellation;
            double wait = ReadWait(m, timeout);
            return WithinStep(m, line, socket, "socket_read_ascii_float", m.Unlocked(() => socket.ReadAsciiFloats(count, wait, token)));
        }, R("number"), O("socket_name", DefaultSocket), O("timeout", 2));
        Add(t, "socket_read_string", (m, line, a) =>
        {
            UrSocket socket = Socket(m, line, a, 0, "socket_read_string");
            double timeout = Num(a, 4, line, "socket_read_string", "timeout");
            FinishBlendBeforeWaiting(m, line, socket);
            CancellationToken token = m.Cancellation;
            double wait = ReadWait(m, timeout);
            return WithinStep(m, line, socket, "socket_read_string", m.Unlocked(() => socket.ReadString(wait, token)));
        }, O("socket_name", DefaultSocket), O("prefix", ""), O("suffix", ""), O("interpret_escape", "False"), O("timeout", 2));
        Add(t, "socket_send_int", (m, line, a) =>
        {
            UrSocket socket = Socket(m, line, a, 1, "socket_send_int");
            // A controller converts a float here as it converts to int anywhere, truncating: the original Machina.NET driver sends
            // socket_send_int(FACTOR_M * pose[0]), which ran on software 3.x.
            int value = UrValue.Int(a[0], line, "socket_send_int: argument 'value'");
            using (m.Unlock())
            {
                return UrValue.Box(socket.SendInt(value));
            }
        },
            R("value"), O("socket_name", DefaultSocket));
        Add(t, "socket_send_byte", (m, line, a) =>
            UrValue.Box(Socket(m, line, a, 1, "socket_send_byte").Send([(byte)Int(a, 0, line, "socket_send_byte", "value")])),
            R("value"), O("socket_name", DefaultSocket));
        Add(t, "socket_send_string", (m, line, a) =>
            UrValue.Box(Socket(m, line, a, 1, "socket_send_string").Send(Encoding.Latin1.GetBytes(UrValue.ToText(a[0])))),
            R("str"), O("socket_name", DefaultSocket));
        Add(t, "socket_send_line", (m, line, a) =>
            UrValue.Box(Socket(m, line, a, 1, "socket_send_line").Send(Encoding.Latin1.GetBytes(UrValue.ToText(a[0]) + "\n"))),
            R("str"), O("socket_name", DefaultSocket));
    }

    private static object SocketOpen(UrMachine m, int line, object[] a)
    {
        string address = Str(a, 0, line, "socket_open", "address");
        int port = Int(a, 1, line, "socket_open", "port");
        string name = Str(a, 2, line, "socket_open", "socket_name");
        if (port < 1 || port > 65535)
        {
            throw new UrRuntimeException(line, $"socket_open: port {port} is not 1 to 65535");
        }
        if (m.Sockets.Remove(name, out UrSocket? old))
        {
            old.Dispose();
        }
        if (m.Controller.Options.Route is { } route)
        {
            System.Net.DnsEndPoint to = route(new System.Net.DnsEndPoint(address, port));
            (address, port) = (to.Host, to.Port);
        }
        CancellationToken token = m.Cancellation;
        TimeSpan timeout = m.Controller.Options.SocketOpenTimeout;
        Twin.TwinWait.Blocking(); // a connect waits: what this thread sent is not held through it
        UrSocket? socket = m.Unlocked(() => UrSocket.Connect(address, port, timeout, token));
        if (socket is null)
        {
            return UrValue.Box(false);
        }
        m.Sockets[name] = socket;
        if (m.Controller.Options.Seam is { } seam)
        {
            socket.Seam = seam;
            socket.Program = token;
            socket.Held = new Twin.TwinHeldOutbox(socket.Connection, m.Sends);
            m.Unlocked(() =>
            {
                seam.Opened(socket, token);
                return 0;
            });
        }
        return UrValue.Box(true);
    }

    /// <summary>
    /// How long a socket read may wait: its timeout, or in a secondary program one controller step ("Secondary Program
    /// Limitations": socket use there is "limited to executing simple non-blocking commands"; a "slow remote server ... will cause
    /// 'Runtime too much behind'").
    /// </summary>
    private static double ReadWait(UrMachine m, double timeout) => m.StepWork > 0 ? UrTwinController.ControlStep : timeout;

    /// <summary>
    /// <paramref name="value"/>, the read's result; in a secondary program a read that found its data incomplete after one
    /// controller step stops the program with <see cref="UrMachine.TooMuchBehind"/> (its protective stop follows).
    /// </summary>
    private static T WithinStep<T>(UrMachine m, int line, UrSocket socket, string function, T value) =>
        m.StepWork > 0 && socket.TimedOut
            ? throw new UrRuntimeException(line, $"{UrMachine.TooMuchBehind} ({function}: a secondary program's read waited past one controller step for data that had not arrived)")
            : value;

    private static UrSocket Socket(UrMachine m, int line, object[] a, int index, string function)
    {
        string name = Str(a, index, line, function, "socket_name");
        return m.Sockets.TryGetValue(name, out UrSocket? socket)
            ? socket
            : throw new UrRuntimeException(line, $"{function}: socket '{name}' is not open");
    }
}

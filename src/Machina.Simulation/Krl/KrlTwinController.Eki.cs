using System.Globalization;
using System.Net.Sockets;

namespace Machina.Simulation.Krl;

/// <summary>
/// EthernetKRL on the twin: channel configurations by name, and the EKI_ functions the Machina driver calls. Errors of a kind
/// the connection causes (sending without a client, initialising twice) come back in Msg_No; mistakes of the program or the
/// configuration (an unknown channel or tag) stop the program.
/// </summary>
internal sealed partial class KrlTwinController
{
    /// <summary>Msg_No when EKI_Send finds no connection.</summary>
    public const int EkiNoConnection = 9;

    /// <summary>Msg_No when EKI_Init is called for a channel already initialised.</summary>
    public const int EkiAlreadyInitialised = 23;

    private readonly Dictionary<string, EkiConfiguration> _ekiConfigurations = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<string, EkiChannel> _ekiChannels = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<string, int> _ekiPorts = new(StringComparer.OrdinalIgnoreCase);
    private readonly Dictionary<string, TcpListener> _ekiReserved = new(StringComparer.OrdinalIgnoreCase);
    private readonly HashSet<string> _ekiNoted = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>Raised when a program opens a channel (EKI_Open): its name, and its protocol, role and address.</summary>
    public event Action<string, string>? EkiOpened;

    /// <summary>How many EthernetKRL channels are initialised (a WAIT FOR may wait on them).</summary>
    public int EkiOpenChannels
    {
        get
        {
            lock (_gate)
            {
                return _ekiChannels.Count;
            }
        }
    }

    /// <summary>Adds the XML configuration of channel <paramref name="name"/> (as in C:\KRC\ROBOTER\Config\User\Common\EthernetKRL).</summary>
    /// <exception cref="FormatException">The configuration is not one the package reads.</exception>
    public void AddEkiConfiguration(string name, string xml)
    {
        EkiConfiguration configuration = EkiConfiguration.Parse(name, xml);
        lock (_gate)
        {
            _ekiConfigurations[name] = configuration;
        }
    }

    /// <summary>The port channel <paramref name="name"/> listens on (its configured port, or the one picked for port 0), or 0 before it opened.</summary>
    public int EkiPort(string name)
    {
        lock (_gate)
        {
            return _ekiPorts.GetValueOrDefault(name);
        }
    }

    /// <summary>
    /// Gives channel <paramref name="name"/> a socket bound already (its port known before the program opens it): EKI_Open accepts
    /// on it, and it keeps listening after EKI_Close (the owner stops it).
    /// </summary>
    public void Reserve(string name, TcpListener listener)
    {
        lock (_gate)
        {
            _ekiReserved[name] = listener;
            _ekiPorts[name] = ((System.Net.IPEndPoint)listener.LocalEndpoint).Port;
        }
    }

    /// <summary>The socket reserved for channel <paramref name="name"/>, or null.</summary>
    internal TcpListener? Reserved(string name)
    {
        lock (_gate)
        {
            return _ekiReserved.GetValueOrDefault(name);
        }
    }

    private void AddEki()
    {
        KrlBuiltinParameter text = KrlBuiltinParameter.Text;
        KrlType status = KrlTypes.EkiStatus;
        void Add(string name, KrlBuiltinParameter[] parameters, Func<KrlMachine, object[], object?> run) =>
            Environment.Builtins[name] = new KrlBuiltin(name, status, parameters, run) { WritesOnlyArguments = true, ReturnsFresh = true };
        Add("EKI_Init", [text], (_, a) => EkiInit(Str(a[0])));
        Add("EKI_Open", [text], (_, a) => EkiOpen(Str(a[0])));
        Add("EKI_Close", [text], (m, a) => EkiClose(Str(a[0]), clear: false, m.Cancellation));
        Add("EKI_Clear", [text], (m, a) => EkiClose(Str(a[0]), clear: true, m.Cancellation));
        Add("EKI_CheckBuffer", [text, text], (_, a) =>
        {
            int buffered = Channel(Str(a[0])).Count(Str(a[1]), out bool connected);
            return Status(buffered, 0, 0, connected);
        });
        Add("EKI_ClearBuffer", [text, text], (_, a) =>
        {
            EkiChannel channel = Channel(Str(a[0]));
            string tag = Str(a[1]);
            if (!channel.Receives(tag) && NotedOnce($"{channel.Name}/{tag}"))
            {
                // Machina.NET's published driver clears its SEND element R after each acknowledgement and runs on controllers:
                // the program goes on (the controller's message number for it is not known).
                Pendant.Log($"EthernetKRL {channel.Name}: EKI_ClearBuffer of {tag}, which the channel does not receive: nothing cleared (noted once)");
            }
            channel.ClearBuffer(tag);
            return Status(0, 0, 0, channel.Connected);
        });
        Add("EKI_GetInt", [text, text, new(KrlType.Int, IsOut: true)], (_, a) => EkiGet(a, EkiInt));
        Add("EKI_GetReal", [text, text, new(KrlType.Real, IsOut: true)], (_, a) => EkiGet(a, null));
        Add("EKI_GetBool", [text, text, new(KrlType.Bool, IsOut: true)], (_, a) => EkiGet(a, EkiBool));
        Add("EKI_GetString", [text, text, new(KrlType.Array(KrlType.Char, 0), IsOut: true)], (_, a) => EkiGet(a, v => v));
        foreach ((string suffix, KrlType element, Func<string, object> convert) in new (string, KrlType, Func<string, object>)[]
        {
            ("Int", KrlType.Int, EkiInt), ("Real", KrlType.Real, EkiReal), ("Bool", KrlType.Bool, EkiBool),
        })
        {
            Add($"EKI_Get{suffix}Array", [text, text, new(KrlType.Array(element, 0), IsOut: true)], (_, a) => EkiGetArray(a, convert));
        }
        Add("EKI_GetFrame", [text, text, new(KrlTypes.Frame, IsOut: true)], (_, a) => EkiGet(a, v =>
        {
            double[] parts = EkiChannel.ParseFrame(v);
            return new KrlStructValue(KrlTypes.Frame, [.. parts.Select(p => (object)p)]);
        }));
        Add("EKI_SetFrame", [text, text, new(KrlTypes.Frame)], (_, a) =>
        {
            EkiChannel channel = Channel(Str(a[0]));
            var frame = (KrlStructValue)KrlConvert.To(KrlTypes.Frame, a[2], KrlValues.Default(KrlTypes.Frame));
            channel.SetFrame(Str(a[1]), [.. EkiChannel.FrameComponents.Select(frame.Number)]);
            return Status(0, 0, 0, channel.Connected);
        });
        Add("EKI_SetInt", [text, text, KrlBuiltinParameter.Int], (_, a) => EkiSet(a, KrlValues.ToInt(a[2]).ToString(CultureInfo.InvariantCulture)));
        Add("EKI_SetReal", [text, text, KrlBuiltinParameter.Real], (_, a) => EkiSet(a, EkiChannel.Format(KrlValues.ToReal(a[2]))));
        Add("EKI_SetBool", [text, text, new(KrlType.Bool)], (_, a) => EkiSet(a, (bool)a[2] ? "1" : "0"));
        Add("EKI_SetString", [text, text, text], (_, a) => EkiSet(a, Str(a[2])));
        Add("EKI_Send", [text, text], (_, a) =>
        {
            EkiChannel channel = Channel(Str(a[0]));
            bool sent = channel.Send(Str(a[1]));
            return Status(0, 0, sent ? 0 : EkiNoConnection, channel.Connected);
        });
    }

    /// <summary>Whether <paramref name="key"/> is noted for the first time (a pendant note that a loop would repeat is shown once).</summary>
    private bool NotedOnce(string key)
    {
        lock (_gate)
        {
            return _ekiNoted.Add(key);
        }
    }

    private static string Str(object value) => value is string s ? s : KrlValues.Text((KrlArrayValue)value);

    /// <summary>The statuses without an error for Buff 0 to 127, Read 0 or 1 and either Connected, made when first returned.</summary>
    private readonly KrlStructValue?[] _statuses = new KrlStructValue?[128 * 2 * 2];

    /// <summary>
    /// An EKI_STATUS. One without an error and a small Buff is kept and returned again (<see cref="KrlStructValue.Shared"/>: a
    /// program that writes a component of it gets a copy): the driver's 13 EthernetKRL calls an action made 13 structures.
    /// </summary>
    private KrlStructValue Status(int buffered, int read, int error, bool connected)
    {
        if (error != 0 || buffered is < 0 or >= 128 || read is < 0 or > 1)
        {
            return NewStatus(buffered, read, error, connected, shared: false);
        }
        int index = (buffered * 2 + read) * 2 + (connected ? 1 : 0);
        // Two interpreters (robot and submit) may make the same one at once: either is kept, both are equal and never written.
        return _statuses[index] ??= NewStatus(buffered, read, error, connected, shared: true);
    }

    private static KrlStructValue NewStatus(int buffered, int read, int error, bool connected, bool shared) =>
        new(KrlTypes.EkiStatus, [KrlValues.Box(buffered), KrlValues.Box(read), KrlValues.Box(error), KrlValues.Box(connected), KrlValues.Box(0)]) { Shared = shared };

    /// <summary>The channel an EKI_ function found last, by the name it was given (an interpreter names the same one call after call).</summary>
    private sealed record LastChannel(string Name, EkiChannel Channel);

    /// <summary>Set under the gate with the channels it was found among; null again whenever a channel is added or removed.</summary>
    private volatile LastChannel? _lastChannel;

    private EkiChannel Channel(string name)
    {
        if (_lastChannel is { } last && string.Equals(last.Name, name, StringComparison.OrdinalIgnoreCase))
        {
            return last.Channel;
        }
        lock (_gate)
        {
            if (!_ekiChannels.TryGetValue(name, out EkiChannel? channel))
            {
                throw new KrlRuntimeException($"EthernetKRL: the channel {name} is not initialised (EKI_Init)");
            }
            _lastChannel = new LastChannel(name, channel);
            return channel;
        }
    }

    private KrlStructValue EkiInit(string name)
    {
        lock (_gate)
        {
            if (_ekiChannels.ContainsKey(name))
            {
                return Status(0, 0, EkiAlreadyInitialised, _ekiChannels[name].Connected);
            }
            if (!_ekiConfigurations.TryGetValue(name, out EkiConfiguration? configuration))
            {
                throw new KrlRuntimeException($"EthernetKRL: no configuration {name}.xml on the controller");
            }
            _ekiChannels[name] = new EkiChannel(name, configuration, this);
            _lastChannel = null;
        }
        InputsChanged();
        return Status(0, 0, 0, false);
    }

    private KrlStructValue EkiOpen(string name)
    {
        EkiChannel channel = Channel(name);
        int port = EkiPort(name) is > 0 and var known && channel.Configuration.Port == 0 ? known : channel.Configuration.Port;
        int bound = channel.Open(Options.ListenAddress, port);
        lock (_gate)
        {
            _ekiPorts[name] = bound;
        }
        EkiConfiguration configuration = channel.Configuration;
        EkiOpened?.Invoke(name, FormattableString.Invariant($"{(configuration.Udp ? "UDP" : "TCP")} {(configuration.RobotIsServer
            ? $"server on {Options.ListenAddress}:{bound}" : $"client of {configuration.Address}:{bound}")}"));
        return Status(0, 0, 0, channel.Connected);
    }

    private KrlStructValue EkiClose(string name, bool clear, CancellationToken cancellation)
    {
        EkiChannel channel = Channel(name);
        channel.Close(cancellation);
        if (clear)
        {
            lock (_gate)
            {
                _ekiChannels.Remove(name);
                _lastChannel = null;
            }
            channel.Dispose();
            InputsChanged();
        }
        return Status(0, 0, 0, false);
    }

    /// <summary>True while channel <paramref name="name"/> is initialised and has a client connected.</summary>
    public bool EkiConnected(string name)
    {
        lock (_gate)
        {
            return _ekiChannels.TryGetValue(name, out EkiChannel? channel) && channel.Connected;
        }
    }

    /// <summary>
    /// What a program reset does to a channel linked to the robot interpreter (ENVIRONMENT Program): as EKI_Clear, the connection
    /// ends and the memories are emptied; the program initialises it again. Nothing when it is not initialised.
    /// </summary>
    public void ClearEki(string name)
    {
        EkiChannel? channel;
        lock (_gate)
        {
            if (!_ekiChannels.Remove(name, out channel))
            {
                return;
            }
            _lastChannel = null;
        }
        channel.Close();
        channel.Dispose();
        InputsChanged();
    }

    /// <summary>EKI_GetInt, EKI_GetReal, EKI_GetBool, EKI_GetString...: the tag's next value into the OUT argument, read with <paramref name="convert"/> (null: a REAL, stored unboxed).</summary>
    private KrlStructValue EkiGet(object[] a, Func<string, object>? convert)
    {
        EkiChannel channel = Channel(Str(a[0]));
        string? value = channel.Take(Str(a[1]), out int remaining, out bool connected);
        if (value is not null)
        {
            try
            {
                var place = (KrlPlace)a[2];
                if (convert is null)
                {
                    place.SetReal(ParseReal(value)); // EKI_GetReal: into a REAL array's element or a structure's component without a box
                }
                else
                {
                    place.Set(convert(value));
                }
            }
            catch (FormatException)
            {
                throw new KrlRuntimeException($"EthernetKRL: the value \"{value}\" of {Str(a[1])} is not a number");
            }
        }
        return Status(remaining, value is null ? 0 : 1, 0, connected);
    }

    /// <summary>
    /// An INT element's value: the number rounded to the nearest INT. Text that is an integer already (an optional sign and digits,
    /// as the driver's IDs and types are) is read as one; anything else (a fraction, an exponent, spaces) as a REAL first, rounded.
    /// </summary>
    private static object EkiInt(string value) => KrlValues.Box(int.TryParse(value, NumberStyles.AllowLeadingSign, CultureInfo.InvariantCulture, out int whole)
        ? whole
        : (int)Math.Round(double.Parse(value, CultureInfo.InvariantCulture)));

    /// <summary>A REAL element's value: plain decimal text (the host's numbers) read directly (<see cref="KrlDecimalText"/>), the rest as before.</summary>
    private static object EkiReal(string value) => ParseReal(value);

    /// <summary>The REAL <see cref="EkiReal"/> reads, unboxed.</summary>
    private static double ParseReal(string value) => KrlDecimalText.TryRead(value, out double number) ? number : double.Parse(value, CultureInfo.InvariantCulture);

    private static object EkiBool(string value) => KrlValues.Box(value is "1" || value.Equals("true", StringComparison.OrdinalIgnoreCase));

    /// <summary>
    /// EKI_GetIntArray, EKI_GetRealArray, EKI_GetBoolArray: the next values of the tag's memory into the array from its first
    /// element, until the array is full or the memory empty (the elements after the last read keep their values); Read is how
    /// many were read, Buff how many remain.
    /// </summary>
    private KrlStructValue EkiGetArray(object[] a, Func<string, object> convert)
    {
        EkiChannel channel = Channel(Str(a[0]));
        var place = (KrlPlace)a[2];
        var array = (KrlArrayValue)place.Get();
        object[] items = array.ToObjects();
        int read = 0, remaining = channel.Count(Str(a[1]));
        while (read < items.Length && channel.Take(Str(a[1]), out remaining) is { } value)
        {
            try
            {
                items[read++] = convert(value);
            }
            catch (FormatException)
            {
                throw new KrlRuntimeException($"EthernetKRL: the value \"{value}\" of {Str(a[1])} is not a number");
            }
        }
        place.Set(new KrlArrayValue(array.Type, items));
        return Status(remaining, read, 0, channel.Connected);
    }

    private KrlStructValue EkiSet(object[] a, string value)
    {
        EkiChannel channel = Channel(Str(a[0]));
        channel.Set(Str(a[1]), value);
        return Status(0, 0, 0, channel.Connected);
    }

    private void CloseEki()
    {
        List<EkiChannel> channels;
        lock (_gate)
        {
            channels = [.. _ekiChannels.Values];
            _ekiChannels.Clear();
            _lastChannel = null;
        }
        foreach (EkiChannel channel in channels)
        {
            channel.Dispose();
        }
    }
}

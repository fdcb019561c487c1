using System.Net.Sockets;
using System.Text;
using System.Text.RegularExpressions;

namespace Machina.Simulation;

public sealed partial class VirtualUrController
{
    /// <summary>Largest script accepted, in bytes (Machina's driver is about 6 KB).</summary>
    internal const int MaxScriptLength = 256 * 1024;

    private static readonly Regex HostLine = new("^[ \\t]*HOSTNAME[ \\t]*=[ \\t]*\"([^\"\\n]*)\"", RegexOptions.Multiline | RegexOptions.CultureInvariant);
    private static readonly Regex PortLine = new("^[ \\t]*PORT[ \\t]*=[ \\t]*([0-9]{1,5})[ \\t]*(#.*)?$", RegexOptions.Multiline | RegexOptions.CultureInvariant);
    private static readonly Regex InstanceLine = new("^[ \\t]*INSTANCE[ \\t]*=[ \\t]*(-?[0-9]{1,10})[ \\t]*(#.*)?$", RegexOptions.Multiline | RegexOptions.CultureInvariant);
    private static readonly Regex OursLine = new("^[ \\t]*MACHINA_DRIVER_VERSION[ \\t]*=[ \\t]*\\[[ \\t]*2[ \\t]*,", RegexOptions.Multiline | RegexOptions.CultureInvariant);
    private static readonly Regex OriginalLine = new("^[ \\t]*MACHINA_DRIVER_VERSION[ \\t]*=[ \\t]*\"1\\.", RegexOptions.Multiline | RegexOptions.CultureInvariant);

    private readonly List<string> _scripts = [];
    private readonly List<NetworkStream> _scriptStreams = [];

    /// <summary>Which Machina driver a script is.</summary>
    internal enum DriverKind
    {
        /// <summary>Not a Machina driver.</summary>
        None,

        /// <summary>Machina's driver (drivers/ur, version 2).</summary>
        Ours,

        /// <summary>The original Machina.NET driver (version 1.x).</summary>
        Original,
    }

    /// <summary>How many scripts arrived on the script ports (driver or not).</summary>
    public int ScriptsReceived
    {
        get
        {
            lock (Gate)
            {
                return _scripts.Count;
            }
        }
    }

    /// <summary>The last script received, or null.</summary>
    public string? LastScript
    {
        get
        {
            lock (Gate)
            {
                return _scripts.Count == 0 ? null : _scripts[^1];
            }
        }
    }

    private Task AcceptScriptsAsync(TcpListener listener, CancellationToken token) => AcceptAsync(listener, ReadScriptsAsync, token);

    /// <summary>
    /// Reads scripts from one connection, as the script manual says a controller recognises them: a program starts with
    /// <c>def</c> or <c>sec</c> in column 1 and is complete at its <c>end</c> in column 1 (a line break after it is not
    /// waited for); any other unindented line is a one-line script, complete at its line break or when the connection closes.
    /// </summary>
    private async Task ReadScriptsAsync(TcpClient client, CancellationToken token)
    {
        var stream = client.GetStream();
        lock (Gate)
        {
            _scriptStreams.Add(stream);
        }
        try
        {
            if (Twin is { } twin)
            {
                await FeedTwinAsync(stream, twin, token).ConfigureAwait(false);
            }
            else
            {
                await ReadScriptsAsync(stream, token).ConfigureAwait(false);
            }
        }
        finally
        {
            lock (Gate)
            {
                _scriptStreams.Remove(stream);
            }
        }
    }

    private async Task ReadScriptsAsync(NetworkStream stream, CancellationToken token)
    {
        var text = new StringBuilder();
        var bytes = new byte[8192];
        string? awaitingCall = null; // a program whose definition ran without the call that usually follows it
        bool closed = false;
        while (!closed)
        {
            int n = await stream.ReadAsync(bytes, token).ConfigureAwait(false);
            if (n == 0)
            {
                closed = true;
            }
            else
            {
                text.Append(Encoding.ASCII.GetString(bytes, 0, n));
            }
            if (text.Length > MaxScriptLength)
            {
                RecordError($"refused a script longer than {MaxScriptLength} bytes.");
                return;
            }
            while (TakeScript(text.ToString(), closed) is (string script, int length))
            {
                text.Remove(0, length);
                if (awaitingCall is not null && IsOnlyCallOf(script, awaitingCall))
                {
                    // The call line after a program's end (the original Machina.NET host sends one): part of the same
                    // upload, not a new script that would replace the program it just started.
                    AppendToLastScript(script);
                    awaitingCall = null;
                    continue;
                }
                awaitingCall = DefinedWithoutCall(script);
                await RunScriptAsync(script, token).ConfigureAwait(false);
            }
        }
    }

    /// <summary>
    /// The first complete script at the start of <paramref name="text"/> and how many characters it takes (blank and comment
    /// lines before it included), or null when more text is needed. <paramref name="closed"/>: nothing more will come, so a
    /// last line without its line break counts.
    /// </summary>
    internal static (string Script, int Length)? TakeScript(string text, bool closed)
    {
        int at = 0;
        bool inProgram = false;
        while (at < text.Length)
        {
            int lineEnd = text.IndexOf('\n', at);
            bool hasBreak = lineEnd >= 0;
            int next = hasBreak ? lineEnd + 1 : text.Length;
            string line = text[at..(hasBreak ? lineEnd : text.Length)].TrimEnd('\r');
            bool topLevel = line.Length > 0 && !char.IsWhiteSpace(line[0]) && !line.StartsWith('#');
            if (!inProgram && topLevel)
            {
                if (line.StartsWith("def ", StringComparison.Ordinal) || line.StartsWith("sec ", StringComparison.Ordinal))
                {
                    inProgram = true;
                }
                else
                {
                    return hasBreak || closed ? (text[..next], next) : null; // a one-line script
                }
            }
            else if (inProgram && topLevel && line.TrimEnd() == "end")
            {
                return (text[..next], next); // the program's end in column 1: complete, with or without its line break
            }
            if (!hasBreak)
            {
                return null;
            }
            at = next;
        }
        return null;
    }

    /// <summary>The name of the program a script defines when the script ends with that definition's <c>end</c> (no call after it), else null.</summary>
    internal static string? DefinedWithoutCall(string script)
    {
        List<string> top = TopLevelLines(script);
        if (top.Count == 0 || top[^1] != "end")
        {
            return null;
        }
        string? def = top.LastOrDefault(l => l.StartsWith("def ", StringComparison.Ordinal));
        int open = def?.IndexOf('(') ?? -1;
        return open > 4 ? def![4..open].Trim() : null;
    }

    /// <summary>True when a script is nothing but the call of <paramref name="program"/> (blank and comment lines aside).</summary>
    internal static bool IsOnlyCallOf(string script, string program) =>
        script.Split('\n').Select(l => l.Trim()).Where(l => l.Length > 0 && !l.StartsWith('#')).ToList() is [string only]
        && only.Replace(" ", "", StringComparison.Ordinal) == program + "()";

    /// <summary>The unindented lines of a script that are neither blank nor comments, trimmed.</summary>
    private static List<string> TopLevelLines(string script) =>
        [.. script.Split('\n').Where(l => l.Length > 0 && !char.IsWhiteSpace(l[0]) && !l.StartsWith('#')).Select(l => l.TrimEnd())];

    private void AppendToLastScript(string text)
    {
        lock (Gate)
        {
            if (_scripts.Count > 0)
            {
                _scripts[^1] += text;
            }
        }
    }

    /// <summary>What a script is, and where it connects back to.</summary>
    internal static (DriverKind Kind, string? Host, int Port) Recognise(string script)
    {
        if (!script.Contains("def machina_ur_driver():", StringComparison.Ordinal))
        {
            return (DriverKind.None, null, 0);
        }
        DriverKind kind = OursLine.IsMatch(script) ? DriverKind.Ours : OriginalLine.IsMatch(script) ? DriverKind.Original : DriverKind.None;
        Match host = HostLine.Match(script), port = PortLine.Match(script);
        if (kind == DriverKind.None || !host.Success || !port.Success || !int.TryParse(port.Groups[1].Value, Num.Inv, out int p) || p is < 1 or > 65535)
        {
            return (DriverKind.None, null, 0);
        }
        return (kind, host.Groups[1].Value, p);
    }

    /// <summary>
    /// Sends a runtime exception to every connection on the script ports, as a primary/secondary client interface does: a
    /// robot message package (size, type 20, timestamp, source, message type 10, script line and column, then the text).
    /// </summary>
    private void SendRuntimeException(int line, string text)
    {
        byte[] bytes = UrRobotMessage.RuntimeException((ulong)Clock.GetElapsedTime(0).TotalMilliseconds, line, 0, text);
        NetworkStream[] streams;
        lock (Gate)
        {
            streams = [.. _scriptStreams];
        }
        foreach (NetworkStream stream in streams)
        {
            Run(async token =>
            {
                try
                {
                    await stream.WriteAsync(bytes, token).ConfigureAwait(false);
                }
                catch (Exception e) when (e is IOException or SocketException or ObjectDisposedException or OperationCanceledException)
                {
                    // That client is gone.
                }
            });
        }
    }

    /// <summary>The instance number our driver publishes in output_int_register_26 (its <c>INSTANCE</c> line), or 0 without one.</summary>
    internal static int InstanceOf(string script)
    {
        Match m = InstanceLine.Match(script);
        return m.Success && int.TryParse(m.Groups[1].Value, Num.Inv, out int instance) ? instance : 0;
    }

    /// <summary>Runs a script as a real controller would: it replaces the running program; a Machina driver connects back.</summary>
    private async Task RunScriptAsync(string script, CancellationToken token)
    {
        lock (Gate)
        {
            _scripts.Add(script);
            if (_scripts.Count > MaxKeptTexts)
            {
                _scripts.RemoveAt(0);
            }
        }
        var (kind, host, port) = Recognise(script);
        StopProgram(kind == DriverKind.None ? "a new script replaces it" : "a new driver replaces it");
        if (kind == DriverKind.None)
        {
            string first = script.Split('\n').Select(l => l.Trim()).FirstOrDefault(l => l.Length > 0 && !l.StartsWith('#')) ?? "";
            RecordError($"refused a script that is not Machina's driver (no machina_ur_driver with its version, HOSTNAME and PORT); it begins \"{Shorten(first)}\".");
            return;
        }
        Pendant(kind == DriverKind.Ours ? "Machina driver 2.0.0 started" : "Started Machina driver (original 1.x)");
        int program = StartProgram(kind, InstanceOf(script));
        var client = new TcpClient { NoDelay = true };
        try
        {
            using var deadline = CancellationTokenSource.CreateLinkedTokenSource(token);
            deadline.CancelAfter(TimeSpan.FromSeconds(10));
            await client.ConnectAsync(host!, port, deadline.Token).ConfigureAwait(false);
        }
        catch (Exception e) when (e is SocketException or OperationCanceledException)
        {
            client.Dispose();
            RecordError($"the driver could not connect back to {host}:{port}: {e.Message}");
            StopProgram("it could not connect back");
            return;
        }
        if (!await AttachClientAsync(client, (stream, t) => GreetAsync(stream, kind, t), token).ConfigureAwait(false))
        {
            return;
        }
        Run(t => ReadProgramAsync(client, kind, program, t));
    }

    private static string Shorten(string text) => text.Length <= 60 ? text : text[..60] + "…";

    /// <summary>Our driver sends its version, then (both drivers) the full pose: -54, X Y Z RX RY RZ J1..J6, end marker.</summary>
    private async Task GreetAsync(NetworkStream stream, DriverKind kind, CancellationToken token)
    {
        var values = new List<int>(20);
        if (kind == DriverKind.Ours)
        {
            values.AddRange([UrWire.ResponseVersion, 2, 0, 0, UrWire.End]);
        }
        VirtualUrState s = State;
        RotationVector rv = s.Rotation.ToRotationVector();
        values.Add(UrWire.ResponseFullPose);
        values.AddRange([UrWire.Millimetres(s.Position.X), UrWire.Millimetres(s.Position.Y), UrWire.Millimetres(s.Position.Z)]);
        values.AddRange([UrWire.Degrees(rv.X), UrWire.Degrees(rv.Y), UrWire.Degrees(rv.Z)]);
        for (int i = 0; i < Joints.Count; i++)
        {
            values.Add(UrWire.Degrees(s.Joints[i]));
        }
        values.Add(UrWire.End);
        var bytes = new byte[values.Count * 4];
        UrWire.Write(values.ToArray(), bytes);
        await stream.WriteAsync(bytes, token).ConfigureAwait(false);
    }
}

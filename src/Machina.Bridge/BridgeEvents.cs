using System.Buffers;
using System.Text.Encodings.Web;
using System.Text.Json;

namespace Machina.Bridge;

/// <summary>
/// The JSON messages the bridge writes itself (the action and motion events are written by the library's event payloads).
/// Every message is one line with a string <c>event</c>, like the original's.
/// </summary>
internal static class BridgeEvents
{
    /// <summary>Error kinds, as sent in the <c>kind</c> field of an <c>error</c> event.</summary>
    internal static class Kinds
    {
        /// <summary>The text is not a list of Machina instructions (field <c>line</c>, <c>column</c>).</summary>
        internal const string Parse = "parse";

        /// <summary>An instruction is well formed but cannot be applied to the robot's state (field <c>instruction</c>); nothing in the message was issued.</summary>
        internal const string Refused = "refused";

        /// <summary>The message holds no instruction (only spaces, semicolons or comments).</summary>
        internal const string Empty = "empty";

        /// <summary>The WebSocket message itself is not acceptable: binary, too large, or not UTF-8 text.</summary>
        internal const string Frame = "frame";

        /// <summary>The bridge failed unexpectedly while handling the message (a bug; it is logged).</summary>
        internal const string Internal = "internal";

        /// <summary>A control (<c>#pause</c>, <c>#resume</c>, <c>#stop</c>) could not be done: not connected to a brand that can, or the controller refused.</summary>
        internal const string Control = "control";

        /// <summary>Every kind above.</summary>
        internal static readonly IReadOnlyList<string> All = [Parse, Refused, Empty, Frame, Internal, Control];
    }

    private static readonly JsonWriterOptions Options = new() { Encoder = JavaScriptEncoder.UnsafeRelaxedJsonEscaping, Indented = false };

    /// <summary><c>{"event":"controller-disconnected"}</c>: a message arrived while no controller is connected; it was dropped.</summary>
    internal const string ControllerDisconnected = "{\"event\":\"controller-disconnected\"}";

    /// <summary><c>{"event":"client-disconnected","user":"GH"}</c>: the client of that name (or address) left.</summary>
    internal static string ClientDisconnected(string user) => Write(w =>
    {
        w.WriteString("event", "client-disconnected");
        w.WriteString("user", user);
    });

    /// <summary><c>{"event":"control","command":"stop","user":"GH"}</c>: the controller did the control that client sent (pause, resume or stop).</summary>
    internal static string Control(string command, string user) => Write(w =>
    {
        w.WriteString("event", "control");
        w.WriteString("command", command);
        w.WriteString("user", user);
    });

    /// <summary>
    /// <c>{"event":"arm","links":[[0,0,0],…]}</c>: where the arm's joints are, base to flange (mm, rounded to 0.1), for the clients
    /// that asked for it (<c>?arm=1</c>).
    /// </summary>
    internal static string Arm(IReadOnlyList<Vector> links) => Write(w =>
    {
        w.WriteString("event", "arm");
        w.WriteStartArray("links");
        foreach (Vector p in links)
        {
            w.WriteStartArray();
            w.WriteNumberValue(Math.Round(p.X, 1) + 0.0);
            w.WriteNumberValue(Math.Round(p.Y, 1) + 0.0);
            w.WriteNumberValue(Math.Round(p.Z, 1) + 0.0);
            w.WriteEndArray();
        }
        w.WriteEndArray();
    });

    /// <summary><c>{"event":"error","kind":"…","message":"…"}</c> plus details, sent only to the client whose message failed.</summary>
    internal static string Error(string kind, string message, Action<Utf8JsonWriter>? details = null) => Write(w =>
    {
        w.WriteString("event", "error");
        w.WriteString("kind", kind);
        w.WriteString("message", message);
        details?.Invoke(w);
    });

    /// <summary>An error event for text that could not be read, with the line and column (from 1) of the problem.</summary>
    internal static string ParseError(InstructionParseException e) => Error(Kinds.Parse, e.Message, w =>
    {
        w.WriteNumber("line", e.Line);
        w.WriteNumber("column", e.Column);
    });

    /// <summary>An error event for an instruction the robot's state refused.</summary>
    internal static string Refused(ActionRefusedException e) => Error(Kinds.Refused, e.Message, w => w.WriteString("instruction", e.Action.ToInstruction()));

    private static string Write(Action<Utf8JsonWriter> body)
    {
        var buffer = new ArrayBufferWriter<byte>(128);
        using (var w = new Utf8JsonWriter(buffer, Options))
        {
            w.WriteStartObject();
            body(w);
            w.WriteEndObject();
        }
        return System.Text.Encoding.UTF8.GetString(buffer.WrittenSpan);
    }
}

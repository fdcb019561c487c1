using System.Text;
using System.Text.Json;

namespace Machina.Bridge;

/// <summary>The page the bridge serves at <c>/</c>: one HTML file with its script, embedded in this assembly.</summary>
internal static class BridgePage
{
    private const string ResourceName = "Machina.Bridge.Page.index.html";
    private const string PathPlaceholder = "\"__BRIDGE_PATH__\"";

    /// <summary>The page's bytes, with the WebSocket path filled in.</summary>
    internal static byte[] Render(string socketPath)
    {
        using Stream stream = typeof(BridgePage).Assembly.GetManifestResourceStream(ResourceName)
            ?? throw new InvalidOperationException($"The bridge page ({ResourceName}) is missing from the assembly.");
        using var reader = new StreamReader(stream, Encoding.UTF8);
        string html = reader.ReadToEnd();
        // JSON string text is also a valid JavaScript string literal; '<' is escaped so that it cannot end the script element.
        string literal = JsonString(socketPath);
        return Encoding.UTF8.GetBytes(html.Replace(PathPlaceholder, literal, StringComparison.Ordinal));
    }

    /// <summary><paramref name="text"/> as a JSON string with the default (HTML-safe) escaping, written without reflection so that it trims.</summary>
    private static string JsonString(string text)
    {
        var buffer = new System.Buffers.ArrayBufferWriter<byte>(text.Length + 16);
        using (var writer = new Utf8JsonWriter(buffer))
        {
            writer.WriteStringValue(text);
        }
        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }
}

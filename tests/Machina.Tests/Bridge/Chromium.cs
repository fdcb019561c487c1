using System.Collections.Concurrent;
using System.Diagnostics;
using System.Net.WebSockets;
using System.Text;
using System.Text.Json;
using System.Text.RegularExpressions;

namespace Machina.Tests.Bridge;

/// <summary>A test that needs a headless Chromium: skipped when it is not installed, except in CI (CI=true), where it must run.</summary>
public sealed class ChromiumFactAttribute : FactAttribute
{
    /// <summary>Sets <see cref="FactAttribute.Skip"/> when Chromium is missing outside CI.</summary>
    public ChromiumFactAttribute()
    {
        if (Chromium.FindExecutable() is null && !Chromium.InCi)
        {
            Skip = "Chromium is not installed (apt-get install chromium, or set CHROMIUM to its path); this test always runs when CI=true.";
        }
    }
}

/// <summary>
/// A headless Chromium with a fresh profile, driven through the DevTools protocol over a WebSocket: open a page, evaluate
/// script, take a screenshot. Every wait is bounded; the browser process (and only it, with its children) is killed at the end.
/// </summary>
internal sealed partial class Chromium : IAsyncDisposable
{
    private static readonly TimeSpan Limit = TimeSpan.FromSeconds(90);
    private readonly Process _process;
    private readonly string _profile;
    private readonly ClientWebSocket _socket = new();
    private readonly ConcurrentDictionary<int, TaskCompletionSource<JsonElement>> _calls = new();
    private readonly SemaphoreSlim _sendLock = new(1, 1);
    private Task? _pump;
    private int _nextId;
    private string? _session;

    private Chromium(Process process, string profile)
    {
        _process = process;
        _profile = profile;
    }

    internal static bool InCi => string.Equals(Environment.GetEnvironmentVariable("CI"), "true", StringComparison.OrdinalIgnoreCase);

    /// <summary>The browser to run: $CHROMIUM, else chromium (or chromium-browser) on the PATH.</summary>
    internal static string? FindExecutable()
    {
        if (Environment.GetEnvironmentVariable("CHROMIUM") is { Length: > 0 } given && File.Exists(given))
        {
            return given;
        }
        foreach (string dir in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            foreach (string name in new[] { "chromium", "chromium-browser" })
            {
                string path = Path.Combine(dir, name);
                if (File.Exists(path))
                {
                    return path;
                }
            }
        }
        return null;
    }

    /// <summary>Starts the browser headless with a fresh profile and opens one blank tab of <paramref name="width"/> × <paramref name="height"/> pixels.</summary>
    internal static async Task<Chromium> StartAsync(int width, int height)
    {
        string executable = FindExecutable() ?? throw new InvalidOperationException(
            "Chromium is required here (CI=true) but was not found: install it (apt-get install chromium) or set CHROMIUM to its path.");
        string profile = Directory.CreateTempSubdirectory("machina-chromium-").FullName;
        var start = new ProcessStartInfo(executable)
        {
            RedirectStandardError = true,
            RedirectStandardOutput = true,
            UseShellExecute = false,
        };
        foreach (string arg in new[]
        {
            "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--no-default-browser-check",
            "--disable-background-networking", "--disable-component-update", "--disable-sync", "--disable-extensions",
            "--disable-dev-shm-usage", "--hide-scrollbars", "--mute-audio", $"--window-size={width},{height}",
            $"--user-data-dir={profile}", "--remote-debugging-port=0", "--remote-debugging-address=127.0.0.1", "about:blank",
        })
        {
            start.ArgumentList.Add(arg);
        }
        var listening = new TaskCompletionSource<string>(TaskCreationOptions.RunContinuationsAsynchronously);
        var stderr = new StringBuilder();
        var process = new Process { StartInfo = start, EnableRaisingEvents = true };
        process.ErrorDataReceived += (_, e) =>
        {
            if (e.Data is null)
            {
                listening.TrySetException(new InvalidOperationException($"Chromium ended before it listened:\n{stderr}"));
                return;
            }
            lock (stderr)
            {
                stderr.AppendLine(e.Data);
            }
            if (DevToolsLine().Match(e.Data) is { Success: true } m)
            {
                listening.TrySetResult(m.Groups[1].Value);
            }
        };
        process.OutputDataReceived += (_, _) => { };
        process.Start();
        process.BeginErrorReadLine();
        process.BeginOutputReadLine();
        var browser = new Chromium(process, profile);
        try
        {
            string url = await listening.Task.WaitAsync(Limit);
            using var timeout = new CancellationTokenSource(Limit);
            browser._socket.Options.KeepAliveInterval = TimeSpan.Zero;
            await browser._socket.ConnectAsync(new Uri(url), timeout.Token);
            browser._pump = Task.Run(browser.PumpAsync);
            JsonElement target = await browser.CallAsync("Target.createTarget", new { url = "about:blank" }, session: false);
            JsonElement attached = await browser.CallAsync("Target.attachToTarget", new { targetId = target.GetProperty("targetId").GetString(), flatten = true }, session: false);
            browser._session = attached.GetProperty("sessionId").GetString();
            await browser.CallAsync("Emulation.setDeviceMetricsOverride", new { width, height, deviceScaleFactor = 1, mobile = false });
            return browser;
        }
        catch
        {
            await browser.DisposeAsync();
            throw;
        }
    }

    [GeneratedRegex(@"DevTools listening on (ws://\S+)")]
    private static partial Regex DevToolsLine();

    /// <summary>Opens <paramref name="url"/> in the tab.</summary>
    internal Task NavigateAsync(Uri url) => CallAsync("Page.navigate", new { url = url.ToString() });

    /// <summary>Evaluates a JavaScript expression in the page and returns its value (JSON-serialisable values only).</summary>
    internal async Task<JsonElement> EvaluateAsync(string expression)
    {
        JsonElement result = await CallAsync("Runtime.evaluate", new { expression, returnByValue = true });
        if (result.TryGetProperty("exceptionDetails", out JsonElement error))
        {
            throw new InvalidOperationException($"The page threw: {error.GetRawText()}");
        }
        JsonElement value = result.GetProperty("result");
        return value.TryGetProperty("value", out JsonElement v) ? v : default;
    }

    /// <summary>Evaluates <paramref name="expression"/> every 50 ms until it returns one of <paramref name="values"/>, at most <see cref="Limit"/>.</summary>
    internal async Task<string> WaitForAsync(string expression, params string[] values)
    {
        long start = TimeProvider.System.GetTimestamp();
        string last = "";
        while (TimeProvider.System.GetElapsedTime(start) < Limit)
        {
            JsonElement v = await EvaluateAsync(expression);
            last = v.ValueKind == JsonValueKind.String ? v.GetString()! : v.GetRawText();
            if (values.Contains(last))
            {
                return last;
            }
            await Task.Delay(50);
        }
        throw new TimeoutException($"The page did not reach {string.Join(" or ", values)} within {Limit.TotalSeconds} s for {expression}; last value: {last}.");
    }

    /// <summary>A PNG of the tab's viewport.</summary>
    internal async Task<byte[]> ScreenshotAsync()
    {
        JsonElement shot = await CallAsync("Page.captureScreenshot", new { format = "png" });
        return Convert.FromBase64String(shot.GetProperty("data").GetString()!);
    }

    private async Task<JsonElement> CallAsync(string method, object parameters, bool session = true)
    {
        int id = Interlocked.Increment(ref _nextId);
        var pending = new TaskCompletionSource<JsonElement>(TaskCreationOptions.RunContinuationsAsynchronously);
        _calls[id] = pending;
        var message = new Dictionary<string, object> { ["id"] = id, ["method"] = method, ["params"] = parameters };
        if (session && _session is not null)
        {
            message["sessionId"] = _session;
        }
        byte[] bytes = JsonSerializer.SerializeToUtf8Bytes(message);
        using var timeout = new CancellationTokenSource(Limit);
        await _sendLock.WaitAsync(timeout.Token);
        try
        {
            await _socket.SendAsync(bytes, WebSocketMessageType.Text, true, timeout.Token);
        }
        finally
        {
            _sendLock.Release();
        }
        JsonElement response = await pending.Task.WaitAsync(Limit);
        if (response.TryGetProperty("error", out JsonElement error))
        {
            throw new InvalidOperationException($"{method} failed: {error.GetRawText()}");
        }
        return response.GetProperty("result");
    }

    private async Task PumpAsync()
    {
        var buffer = new byte[256 * 1024];
        var message = new MemoryStream();
        try
        {
            while (true)
            {
                ValueWebSocketReceiveResult r = await _socket.ReceiveAsync(buffer.AsMemory(), CancellationToken.None);
                if (r.MessageType == WebSocketMessageType.Close)
                {
                    break;
                }
                message.Write(buffer, 0, r.Count);
                if (!r.EndOfMessage)
                {
                    continue;
                }
                JsonElement root = JsonDocument.Parse(message.ToArray()).RootElement.Clone();
                message.SetLength(0);
                if (root.TryGetProperty("id", out JsonElement id) && _calls.TryRemove(id.GetInt32(), out var pending))
                {
                    pending.TrySetResult(root);
                }
            }
        }
        catch (Exception e) when (e is WebSocketException or ObjectDisposedException or OperationCanceledException)
        {
        }
        foreach (var pending in _calls.Values)
        {
            pending.TrySetException(new InvalidOperationException("The DevTools connection closed."));
        }
    }

    public async ValueTask DisposeAsync()
    {
        try
        {
            if (_socket.State == WebSocketState.Open)
            {
                await CallAsync("Browser.close", new { }, session: false).WaitAsync(TimeSpan.FromSeconds(10));
            }
        }
        catch (Exception e) when (e is InvalidOperationException or TimeoutException or WebSocketException)
        {
            // Killed below.
        }
        _socket.Abort();
        if (_pump is not null)
        {
            await _pump.WaitAsync(Limit);
        }
        _socket.Dispose();
        try
        {
            if (!_process.HasExited)
            {
                _process.Kill(entireProcessTree: true);
            }
            await _process.WaitForExitAsync().WaitAsync(Limit);
        }
        catch (InvalidOperationException)
        {
            // Never started.
        }
        _process.Dispose();
        _sendLock.Dispose();
        try
        {
            Directory.Delete(_profile, recursive: true);
        }
        catch (IOException)
        {
            // A file still held by a dying child process; the temp folder is cleaned by the system.
        }
    }
}

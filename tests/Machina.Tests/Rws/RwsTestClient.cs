using System.Net;

namespace Machina.Tests.Rws;

/// <summary>An HTTP client for a twin's Robot Web Services on 127.0.0.1, logged in as RobotStudio's default user.</summary>
internal static class RwsTestClient
{
    /// <summary>A client of the server on <paramref name="port"/>, keeping its session cookies in <paramref name="cookies"/> (a WebSocket reuses them).</summary>
    public static HttpClient For(int port, CookieContainer cookies, TimeSpan timeout) =>
        new(new SocketsHttpHandler { Credentials = new NetworkCredential("Default User", "robotics"), CookieContainer = cookies })
        {
            BaseAddress = new Uri($"http://127.0.0.1:{port}"),
            Timeout = timeout,
        };
}

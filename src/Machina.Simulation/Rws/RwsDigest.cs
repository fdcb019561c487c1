using System.Security.Cryptography;
using System.Text;

namespace Machina.Simulation.Rws;

/// <summary>
/// HTTP digest authentication (RFC 7616, MD5, qop=auth), as RWS 1.0 asks for it: the challenge the server sends and the check of
/// the client's answer against the user's password.
/// </summary>
internal static class RwsDigest
{
    /// <summary>The realm RWS 1.0 controllers name in their challenge.</summary>
    public const string Realm = "validusers@robotcontroller.com";

    /// <summary>The WWW-Authenticate value for <paramref name="nonce"/>; <paramref name="stale"/> when the last answer was right but its nonce expired.</summary>
    public static string Challenge(string nonce, bool stale = false) =>
        $"Digest realm=\"{Realm}\", domain=\"/\", qop=\"auth\", nonce=\"{nonce}\", algorithm=MD5, stale={(stale ? "TRUE" : "FALSE")}";

    /// <summary>A fresh random nonce.</summary>
    public static string NewNonce() => Convert.ToHexString(RandomNumberGenerator.GetBytes(16)).ToLowerInvariant();

    /// <summary>
    /// What <paramref name="authorization"/> is worth for the request <paramref name="method"/> <paramref name="target"/> (the
    /// request line's target, as the client sent it): Fresh when it answers, for this user and password, a nonce of
    /// <paramref name="nonces"/> that is alive and counted up, for this very request (RFC 7616 §3.4.6: its <c>uri</c> is the
    /// request's target); Stale when all is right but the nonce expired; else Unknown. The nonce's count moves only for a right answer.
    /// </summary>
    public static RwsNonceState Verify(string? authorization, string method, string target, string user, string password, RwsNonces nonces)
    {
        if (authorization is null || !authorization.StartsWith("Digest ", StringComparison.OrdinalIgnoreCase))
        {
            return RwsNonceState.Unknown;
        }
        Dictionary<string, string> p = Parameters(authorization[7..]);
        if (!p.TryGetValue("username", out string? name) || name != user || !p.TryGetValue("nonce", out string? nonce)
            || !p.TryGetValue("uri", out string? uri) || uri != target || !p.TryGetValue("response", out string? response)
            || p.GetValueOrDefault("qop") != "auth" || !p.TryGetValue("nc", out string? nc) || !p.TryGetValue("cnonce", out string? cnonce))
        {
            return RwsNonceState.Unknown;
        }
        string ha1 = Md5($"{user}:{Realm}:{password}");
        string ha2 = Md5($"{method}:{uri}");
        string expected = Md5($"{ha1}:{nonce}:{nc}:{cnonce}:auth:{ha2}");
        return CryptographicOperations.FixedTimeEquals(Encoding.ASCII.GetBytes(expected), Encoding.ASCII.GetBytes(response.ToLowerInvariant()))
            ? nonces.Take(nonce, nc)
            : RwsNonceState.Unknown;
    }

    private static Dictionary<string, string> Parameters(string text)
    {
        var result = new Dictionary<string, string>(StringComparer.OrdinalIgnoreCase);
        int i = 0;
        while (i < text.Length)
        {
            while (i < text.Length && (text[i] == ' ' || text[i] == ','))
            {
                i++;
            }
            int eq = text.IndexOf('=', i);
            if (eq < 0)
            {
                break;
            }
            string key = text[i..eq].Trim();
            i = eq + 1;
            string value;
            if (i < text.Length && text[i] == '"')
            {
                int end = text.IndexOf('"', i + 1);
                end = end < 0 ? text.Length : end;
                value = text[(i + 1)..end];
                i = end + 1;
            }
            else
            {
                int end = text.IndexOf(',', i);
                end = end < 0 ? text.Length : end;
                value = text[i..end].Trim();
                i = end;
            }
            result[key] = value;
        }
        return result;
    }

#pragma warning disable CA5351 // Digest authentication of RWS 1.0 is defined with MD5: the twin must speak it to test the client.
    private static string Md5(string text) => Convert.ToHexString(MD5.HashData(Encoding.UTF8.GetBytes(text))).ToLowerInvariant();
#pragma warning restore CA5351
}

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

    /// <summary>The WWW-Authenticate value for <paramref name="nonce"/>.</summary>
    public static string Challenge(string nonce) => $"Digest realm=\"{Realm}\", domain=\"/\", qop=\"auth\", nonce=\"{nonce}\", algorithm=MD5, stale=FALSE";

    /// <summary>A fresh random nonce.</summary>
    public static string NewNonce() => Convert.ToHexString(RandomNumberGenerator.GetBytes(16)).ToLowerInvariant();

    /// <summary>True when <paramref name="authorization"/> answers one of <paramref name="nonces"/> for this user, password and request.</summary>
    public static bool Verify(string? authorization, string method, string user, string password, Func<string, bool> nonces)
    {
        if (authorization is null || !authorization.StartsWith("Digest ", StringComparison.OrdinalIgnoreCase))
        {
            return false;
        }
        Dictionary<string, string> p = Parameters(authorization[7..]);
        if (!p.TryGetValue("username", out string? name) || name != user || !p.TryGetValue("nonce", out string? nonce) || !nonces(nonce)
            || !p.TryGetValue("uri", out string? uri) || !p.TryGetValue("response", out string? response))
        {
            return false;
        }
        string ha1 = Md5($"{user}:{p.GetValueOrDefault("realm", Realm)}:{password}");
        string ha2 = Md5($"{method}:{uri}");
        string expected = p.TryGetValue("qop", out string? qop)
            ? Md5($"{ha1}:{nonce}:{p.GetValueOrDefault("nc")}:{p.GetValueOrDefault("cnonce")}:{qop}:{ha2}")
            : Md5($"{ha1}:{nonce}:{ha2}");
        return CryptographicOperations.FixedTimeEquals(Encoding.ASCII.GetBytes(expected), Encoding.ASCII.GetBytes(response.ToLowerInvariant()));
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

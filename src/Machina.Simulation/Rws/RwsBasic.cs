using System.Security.Cryptography;
using System.Text;

namespace Machina.Simulation.Rws;

/// <summary>HTTP basic authentication (RFC 7617), as RWS 2.0 asks for it (over HTTPS on a controller).</summary>
internal static class RwsBasic
{
    /// <summary>True when <paramref name="authorization"/> is <c>Basic base64(user:password)</c> for this user and password.</summary>
    public static bool Verify(string? authorization, string user, string password)
    {
        if (authorization is null || !authorization.StartsWith("Basic ", StringComparison.OrdinalIgnoreCase))
        {
            return false;
        }
        byte[] given;
        try
        {
            given = Convert.FromBase64String(authorization[6..].Trim());
        }
        catch (FormatException)
        {
            return false;
        }
        return CryptographicOperations.FixedTimeEquals(given, Encoding.UTF8.GetBytes(user + ":" + password));
    }
}

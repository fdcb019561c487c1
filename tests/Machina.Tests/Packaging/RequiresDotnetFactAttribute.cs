using System.Runtime.InteropServices;

namespace Machina.Tests.Packaging;

/// <summary>A test that needs the <c>dotnet</c> command: skipped, with a message saying why, only when it cannot be found.</summary>
public sealed class RequiresDotnetFactAttribute : FactAttribute
{
    /// <summary>Marks the test; sets <see cref="FactAttribute.Skip"/> when no <c>dotnet</c> is found.</summary>
    public RequiresDotnetFactAttribute()
    {
        if (Dotnet.Find() is null)
        {
            Skip = "The dotnet command was not found (neither DOTNET_HOST_PATH nor PATH): the package test cannot run here.";
        }
    }
}

/// <summary>Finds and runs the <c>dotnet</c> command.</summary>
internal static class Dotnet
{
    /// <summary>Full path of <c>dotnet</c>: the one running these tests (DOTNET_HOST_PATH), else the first on PATH; null if none.</summary>
    public static string? Find()
    {
        string name = RuntimeInformation.IsOSPlatform(OSPlatform.Windows) ? "dotnet.exe" : "dotnet";
        string? host = Environment.GetEnvironmentVariable("DOTNET_HOST_PATH");
        if (!string.IsNullOrEmpty(host) && File.Exists(host))
        {
            return host;
        }
        foreach (string folder in (Environment.GetEnvironmentVariable("PATH") ?? "").Split(Path.PathSeparator, StringSplitOptions.RemoveEmptyEntries))
        {
            string candidate = Path.Combine(folder, name);
            if (File.Exists(candidate))
            {
                return candidate;
            }
        }
        return null;
    }
}

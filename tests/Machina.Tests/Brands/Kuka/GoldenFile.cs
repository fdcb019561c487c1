using System.Runtime.CompilerServices;

namespace Machina.Tests.Brands.Kuka;

/// <summary>
/// Compares compiled files with the expected files in Golden/&lt;BRAND&gt;/&lt;Program&gt;[.&lt;variant&gt;].&lt;ext&gt;.
/// With the environment variable MACHINA_UPDATE_GOLDEN=1 the expected files are rewritten instead (then check them by hand).
/// </summary>
internal static class GoldenFile
{
    internal static void Check(RobotProgramFile file, string brand, string variant = "", [CallerFilePath] string callerPath = "")
    {
        string name = file.Name + (variant.Length > 0 ? "." + variant : "") + "." + file.Extension;
        string actual = file.ToText("\n");
        if (Environment.GetEnvironmentVariable("MACHINA_UPDATE_GOLDEN") == "1")
        {
            // callerPath is tests/Machina.Tests/Brands/<Folder>/<File>.cs; the sources of the golden files are in tests/Machina.Tests/Golden.
            string testsRoot = Path.GetFullPath(Path.Combine(Path.GetDirectoryName(callerPath)!, "..", ".."));
            string folder = Path.Combine(testsRoot, "Golden", brand);
            Directory.CreateDirectory(folder);
            File.WriteAllText(Path.Combine(folder, name), actual);
            return;
        }
        string path = Path.Combine(AppContext.BaseDirectory, "Golden", brand, name);
        Assert.True(File.Exists(path), $"Missing golden file {path}; run the tests once with MACHINA_UPDATE_GOLDEN=1 and check the file by hand.");
        string expected = File.ReadAllText(path).Replace("\r\n", "\n", StringComparison.Ordinal);
        Assert.Equal(expected, actual);
    }
}

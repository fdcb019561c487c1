using System.Runtime.CompilerServices;
using Machina.Tests.Support;

namespace Machina.Tests.Brands;

/// <summary>
/// Compares compiled programs with the golden files in Golden/&lt;BRAND&gt;/&lt;Program&gt;[.&lt;variant&gt;].&lt;ext&gt;
/// (copied next to the test assembly). With the environment variable MACHINA_UPDATE_GOLDEN=1 the files in the source tree
/// are rewritten instead; every rewritten file must then be checked by hand before it is committed.
/// </summary>
public static class GoldenFiles
{
    /// <summary>Compiles reference program <paramref name="name"/> for <paramref name="brand"/> and checks every file against its golden file.</summary>
    public static RobotProgram Check(string name, RobotType brand, string? variant = null, CompileOptions? options = null)
    {
        RobotProgram program = ReferencePrograms.Issue(name, brand).Compile(brand, options);
        foreach (RobotProgramFile file in program.Files)
        {
            string relative = Path.Combine("Golden", brand.ToString(), name + (variant is null ? "" : "." + variant) + "." + file.Extension);
            string actual = file.ToText("\n");
            if (Environment.GetEnvironmentVariable("MACHINA_UPDATE_GOLDEN") == "1")
            {
                string target = Path.Combine(SourceRoot(), relative);
                Directory.CreateDirectory(Path.GetDirectoryName(target)!);
                File.WriteAllText(target, actual);
                continue;
            }
            string path = Path.Combine(AppContext.BaseDirectory, relative);
            Assert.True(File.Exists(path), $"Golden file {relative} is missing; run the tests once with MACHINA_UPDATE_GOLDEN=1 and check it by hand.");
            string expected = File.ReadAllText(path).ReplaceLineEndings("\n");
            Assert.Equal(expected, actual);
        }
        return program;
    }

    /// <summary>The test project's folder in the source tree (where Golden/ lives).</summary>
    private static string SourceRoot([CallerFilePath] string thisFile = "") =>
        Path.GetFullPath(Path.Combine(Path.GetDirectoryName(thisFile)!, "..", ".."));
}

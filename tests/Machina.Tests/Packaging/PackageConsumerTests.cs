using System.Diagnostics;
using System.Xml.Linq;

namespace Machina.Tests.Packaging;

/// <summary>
/// The packages as a newcomer gets them: pack Machina and Machina.Simulation into a folder feed, then build and run a fresh
/// console project that references the packages (not the projects) and streams Hello Robot to a virtual ABB controller.
/// Slow (pack, restore, build): one test, bounded to five minutes.
/// </summary>
public class PackageConsumerTests
{
    private static readonly TimeSpan Limit = TimeSpan.FromMinutes(15);

    private const string HelloRobot = """
        using Machina;
        using Machina.Simulation;

        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions { SpeedFactor = 20, Model = RobotModels.Get("IRB 1200-5/0.9") });
        await controller.StartAsync();
        var bot = Robot.Create("HelloRobot", "ABB");
        bot.ControlMode("online");
        bot.ConnectTimeout = TimeSpan.FromMinutes(1);
        int executed = 0;
        Vector? lastPosition = null;
        bot.ActionExecuted += (_, e) => { executed++; lastPosition = e.Position ?? lastPosition; };
        await bot.ConnectAsync("127.0.0.1", controller.Port);

        bot.Message("Hello Robot!");
        bot.SpeedTo(100);
        bot.MoveTo(400, 300, 500);
        bot.Rotate(0, 1, 0, -90);
        bot.Move(0, 0, 250);
        bot.Wait(2000);
        bot.AxesTo(0, 0, 0, 0, 90, 0);

        using var timeout = new CancellationTokenSource(TimeSpan.FromMinutes(2));
        await bot.WaitForCompletionAsync(timeout.Token);
        await bot.DisconnectAsync();
        Console.WriteLine($"executed {executed}");
        Console.WriteLine($"last position {lastPosition}");
        Console.WriteLine($"axes {bot.GetCurrentAxes()}");
        Console.WriteLine($"driver files {string.Join(" ", bot.GetDeviceDriverModules(new Dictionary<string, string> { ["HOSTNAME"] = "127.0.0.1", ["PORT"] = "7000" }).Keys.Order())}");
        """;

    [RequiresDotnetFact]
    public async Task Packages_FreshConsoleProject_RunsHelloRobotFromThePackages()
    {
        string dotnet = Dotnet.Find()!;
        string root = RepositoryRoot();
        string work = Directory.CreateTempSubdirectory("machina-package-test-").FullName;
        using var timeout = new CancellationTokenSource(Limit);
        try
        {
            // Pack from a copy of the sources, so that this test never races the build of the suite itself for obj/.
            string sources = Path.Combine(work, "sources");
            foreach (string file in new[] { "Directory.Build.props", "CHANGELOG.md", "PACKAGE.md", "global.json", "NuGet.Config", ".editorconfig", "docs/icon.png" })
            {
                if (File.Exists(Path.Combine(root, file)))
                {
                    Directory.CreateDirectory(Path.GetDirectoryName(Path.Combine(sources, file))!);
                    File.Copy(Path.Combine(root, file), Path.Combine(sources, file));
                }
            }
            CopySources(Path.Combine(root, "src", "Machina"), Path.Combine(sources, "src", "Machina"));
            CopySources(Path.Combine(root, "src", "Machina.Simulation"), Path.Combine(sources, "src", "Machina.Simulation"));
            CopySources(Path.Combine(root, "drivers"), Path.Combine(sources, "drivers"));
            string feed = Path.Combine(work, "feed");
            foreach (string project in new[] { "Machina", "Machina.Simulation" })
            {
                await RunAsync(dotnet, sources, timeout.Token, "pack", $"src/{project}/{project}.csproj", "-c", "Release", "-o", feed, $"-p:MachinaRepositoryUrl={RepositoryUrl}");
            }
            Assert.True(File.Exists(Path.Combine(feed, "Machina.0.1.0.nupkg")), "Machina.0.1.0.nupkg was not made.");
            Assert.True(File.Exists(Path.Combine(feed, "Machina.Simulation.0.1.0.snupkg")), "Machina.Simulation.0.1.0.snupkg was not made.");
            AssertHasIcon(Path.Combine(feed, "Machina.0.1.0.nupkg"), Path.Combine(root, "docs", "icon.png"));
            AssertHasRepository(Path.Combine(feed, "Machina.0.1.0.nupkg"), RepositoryUrl);
            AssertHasRepository(Path.Combine(feed, "Machina.Simulation.0.1.0.nupkg"), RepositoryUrl);

            // A fresh project, as a newcomer writes it: package references, the folder feed plus the usual sources, and its
            // own packages folder so that an older Machina 0.1.0 in the machine's cache cannot stand in for these.
            string app = Path.Combine(work, "app");
            Directory.CreateDirectory(app);
            File.WriteAllText(Path.Combine(app, "app.csproj"), """
                <Project Sdk="Microsoft.NET.Sdk">
                  <PropertyGroup>
                    <OutputType>Exe</OutputType>
                    <TargetFramework>net10.0</TargetFramework>
                    <Nullable>enable</Nullable>
                    <ImplicitUsings>enable</ImplicitUsings>
                    <TreatWarningsAsErrors>true</TreatWarningsAsErrors>
                  </PropertyGroup>
                  <ItemGroup>
                    <PackageReference Include="Machina" Version="0.1.0" />
                    <PackageReference Include="Machina.Simulation" Version="0.1.0" />
                  </ItemGroup>
                </Project>
                """);
            File.WriteAllText(Path.Combine(app, "Program.cs"), HelloRobot);
            File.WriteAllText(Path.Combine(app, "NuGet.Config"), NuGetConfig(Path.Combine(root, "NuGet.Config"), feed, Path.Combine(work, "packages")));
            File.Copy(Path.Combine(root, "global.json"), Path.Combine(app, "global.json"));

            string output = await RunAsync(dotnet, app, timeout.Token, "run", "-c", "Release");

            string[] lines = output.Split('\n', StringSplitOptions.TrimEntries | StringSplitOptions.RemoveEmptyEntries);
            Assert.Contains("executed 7", lines);
            // The robot learns the twin's IRB 1200 when it connects, so the closing AxesTo has a pose (its forward kinematics).
            Assert.Contains($"last position {new Vector(451, 0, 807.1)}", lines);
            Assert.Contains($"axes {new Joints(0, 0, 0, 0, 90, 0)}", lines);
            Assert.Contains("driver files machina_abb_driver.mod machina_abb_driver.pgf machina_abb_monitor.mod machina_abb_monitor.pgf", lines);
            Assert.True(File.Exists(Path.Combine(work, "packages", "machina", "0.1.0", "lib", "net10.0", "Machina.dll")),
                "The app did not restore Machina from the package.");
        }
        finally
        {
            try
            {
                Directory.Delete(work, recursive: true);
            }
            catch (IOException)
            {
                // A build server may still hold a file; the temp folder is left for the system to clean.
            }
        }
    }

    /// <summary>The usual package sources of the repository's NuGet.Config, with the folder feed first and a private packages folder.</summary>
    private static string NuGetConfig(string repositoryConfig, string feed, string packages)
    {
        string sources = $"""    <add key="machina-test-feed" value="{feed}" />""" + "\n";
        if (File.Exists(repositoryConfig))
        {
            foreach (XElement add in XDocument.Load(repositoryConfig).Descendants("packageSources").Elements("add"))
            {
                sources += $"""    <add key="{add.Attribute("key")?.Value}" value="{add.Attribute("value")?.Value}" />""" + "\n";
            }
        }
        return $"""
            <?xml version="1.0" encoding="utf-8"?>
            <configuration>
              <config>
                <add key="globalPackagesFolder" value="{packages}" />
              </config>
              <packageSources>
                <clear />
            {sources}  </packageSources>
            </configuration>
            """;
    }

    private static void CopySources(string from, string to)
    {
        foreach (string file in Directory.EnumerateFiles(from, "*", SearchOption.AllDirectories))
        {
            string relative = Path.GetRelativePath(from, file);
            string first = relative.Split(Path.DirectorySeparatorChar)[0];
            if (first is "bin" or "obj")
            {
                continue;
            }
            string target = Path.Combine(to, relative);
            Directory.CreateDirectory(Path.GetDirectoryName(target)!);
            File.Copy(file, target);
        }
    }

    private static string RepositoryRoot()
    {
        for (DirectoryInfo? folder = new(AppContext.BaseDirectory); folder is not null; folder = folder.Parent)
        {
            if (File.Exists(Path.Combine(folder.FullName, "Machina.sln")))
            {
                return folder.FullName;
            }
        }
        throw new InvalidOperationException($"No Machina.sln above {AppContext.BaseDirectory}.");
    }

    /// <summary>Runs dotnet with the arguments in a folder; fails the test with the whole output unless it exits with 0.</summary>
    private static async Task<string> RunAsync(string dotnet, string folder, CancellationToken cancellationToken, params string[] arguments)
    {
        var start = new ProcessStartInfo(dotnet)
        {
            WorkingDirectory = folder,
            RedirectStandardOutput = true,
            RedirectStandardError = true,
            UseShellExecute = false,
        };
        foreach (string argument in arguments)
        {
            start.ArgumentList.Add(argument);
        }
        start.Environment["DOTNET_CLI_TELEMETRY_OPTOUT"] = "1";
        start.Environment["DOTNET_NOLOGO"] = "1";
        start.Environment["MSBUILDDISABLENODEREUSE"] = "1";
        // The outer `dotnet test` sets MSBuild variables that must not leak into these separate builds.
        start.Environment.Remove("MSBuildExtensionsPath");
        start.Environment.Remove("MSBuildSDKsPath");
        start.Environment.Remove("MSBUILD_EXE_PATH");
        using var process = Process.Start(start)!;
        Task<string> stdout = process.StandardOutput.ReadToEndAsync(cancellationToken);
        Task<string> stderr = process.StandardError.ReadToEndAsync(cancellationToken);
        try
        {
            await process.WaitForExitAsync(cancellationToken);
        }
        catch (OperationCanceledException)
        {
            process.Kill(entireProcessTree: true);
            Assert.Fail($"dotnet {string.Join(' ', arguments)} took longer than {Limit.TotalMinutes} minutes.");
        }
        string output = await stdout + await stderr;
        Assert.True(process.ExitCode == 0, $"dotnet {string.Join(' ', arguments)} failed with exit code {process.ExitCode}:\n{output}");
        return output;
    }

    /// <summary>The address given to <c>dotnet pack</c> as <c>MachinaRepositoryUrl</c> (a clone with a git remote gets its own from Source Link).</summary>
    private const string RepositoryUrl = "https://git.example/machina/machina.git";

    /// <summary>The package's manifest names the repository (type git, the given address) and the project's page.</summary>
    private static void AssertHasRepository(string package, string url)
    {
        using System.IO.Compression.ZipArchive zip = System.IO.Compression.ZipFile.OpenRead(package);
        System.IO.Compression.ZipArchiveEntry nuspec = zip.Entries.Single(e => e.FullName.EndsWith(".nuspec", StringComparison.Ordinal));
        using Stream stream = nuspec.Open();
        XElement metadata = XDocument.Load(stream).Root!.Elements().Single(e => e.Name.LocalName == "metadata");
        XElement repository = metadata.Elements().Single(e => e.Name.LocalName == "repository");
        Assert.Equal(("git", url), ((string?)repository.Attribute("type"), (string?)repository.Attribute("url")));
        Assert.Equal(url, metadata.Elements().Single(e => e.Name.LocalName == "projectUrl").Value);
    }

    /// <summary>The package names icon.png in its manifest and carries the repository's docs/icon.png, a 128 x 128 PNG, byte for byte.</summary>
    private static void AssertHasIcon(string package, string icon)
    {
        using System.IO.Compression.ZipArchive zip = System.IO.Compression.ZipFile.OpenRead(package);
        System.IO.Compression.ZipArchiveEntry nuspec = zip.Entries.Single(e => e.FullName.EndsWith(".nuspec", StringComparison.Ordinal));
        using (Stream stream = nuspec.Open())
        {
            XElement metadata = XDocument.Load(stream).Root!.Elements().Single(e => e.Name.LocalName == "metadata");
            Assert.Equal("icon.png", metadata.Elements().Single(e => e.Name.LocalName == "icon").Value);
        }
        using var packed = new MemoryStream();
        using (Stream stream = zip.GetEntry("icon.png")!.Open())
        {
            stream.CopyTo(packed);
        }
        byte[] bytes = packed.ToArray();
        Assert.Equal(File.ReadAllBytes(icon), bytes);
        Assert.Equal((128, 128), (System.Buffers.Binary.BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(16)), System.Buffers.Binary.BinaryPrimitives.ReadInt32BigEndian(bytes.AsSpan(20))));
    }
}

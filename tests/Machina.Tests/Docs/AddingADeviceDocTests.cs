using System.Reflection;
using System.Text.RegularExpressions;
using Machina.Simulation;

namespace Machina.Tests.Docs;

/// <summary>
/// docs/adding-a-device.md names real seams: every file it names exists, and every type and member of the seams it
/// describes exists with that name (a rename must update the page).
/// </summary>
public partial class AddingADeviceDocTests
{
    private const string Page = "docs/adding-a-device.md";

    /// <summary>The seams the page explains, and the members of each that it tells a new brand to implement or call.</summary>
    private static readonly (Type Type, string[] Members)[] Seams =
    [
        (typeof(Compiler), ["Brand", "CommentPrefix", "Emit", "Header"]),
        (typeof(Compilers), ["For"]),
        (typeof(CompileJob), ["Replay", "Warn"]),
        (typeof(ProgramOutput), ["OpenFile"]),
        (typeof(ActionKinds), ["Unhandled"]),
        (typeof(IOnlineBrand), ["Brand", "CreateDriver", "WhyCannotStream", "DriverModules"]),
        (typeof(DeviceContext), []),
        (typeof(IDeviceDriver), ["ConnectAsync", "Send", "WireId", "Adopt", "ResumeAsync"]),
        (typeof(IDeviceListener), ["OnAcknowledged", "OnMotion", "OnStopped", "OnResumed", "OnFailed", "OnFault"]),
        (typeof(DeviceDriver<>), ["OpenAsync", "OpenDriverLinkAsync", "OpenMonitorAsync", "OpenSideLinkAsync", "TryReadMotion", "OnMessage", "Handshake",
            "Listener", "Link"]),
        (typeof(IMessageReader<>), ["Append", "TryRead"]),
        (typeof(DriverFiles), ["Read", "Fill"]),
        (typeof(DeviceHandshake), []),
        (typeof(DeviceProgress), []),
        (typeof(OnlineBrands), []),
        (typeof(BrandRegistry), ["All", "Online"]),
        (typeof(BrandDefinition), ["CreateCompiler", "Online", "DefaultPort", "DriverNextSteps"]),
        (typeof(VirtualControllerRegistry), []),
        (typeof(OnlineSession), []),
        (typeof(DriverParameters), []),
        (typeof(TcpLink), []),
        (typeof(KukaOnline), []),
        (typeof(KukaDriver), []),
        (typeof(KukaActionEncoder), ["WhyCannotStream"]),
        (typeof(KukaXmlReader), []),
        (typeof(KukaProtocol), []),
        (typeof(KukaDriverModules), []),
        (typeof(KukaProtocolException), []),
        (typeof(KrlCompiler), []),
        (typeof(KrlWriter), []),
        (typeof(VirtualController<>), ["ListenAsync", "StopListening", "ReceiveOnCaller", "CompleteReceivedOnCaller", "RefuseOnCaller",
            "AfterExecuted", "Acknowledge", "RecordError", "AttachClient", "DropClient"]),
        (typeof(VirtualRobotState), []),
        (typeof(VirtualControllerOptions), ["Validate", "SpeedFactor", "InstantExecution", "TimeProvider"]),
        (typeof(VirtualKukaController), []),
    ];

    [Fact]
    public void AddingADevice_NamesTheRealSeamsAndTheirMembers()
    {
        string text = File.ReadAllText(DocText.PathOf(Page));
        const BindingFlags all = BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static;

        foreach ((Type type, string[] members) in Seams)
        {
            string name = type.IsGenericTypeDefinition ? type.Name[..type.Name.IndexOf('`', StringComparison.Ordinal)] : type.Name;
            Assert.True(Regex.IsMatch(text, $@"\b{name}\b"), $"{Page} does not name {name}.");
            foreach (string member in members)
            {
                Assert.True(type.GetMember(member, all).Length > 0, $"{type.Name} has no member {member}, which {Page} names.");
                Assert.True(text.Contains(member, StringComparison.Ordinal), $"{Page} does not name {type.Name}.{member}.");
            }
        }
    }

    [Fact]
    public void AddingADevice_EveryFileItNamesExists()
    {
        string text = File.ReadAllText(DocText.PathOf(Page));
        string root = Conventions.ConventionTests.RepositoryRoot();
        var files = Directory.EnumerateFiles(root, "*.*", SearchOption.AllDirectories)
            .Where(f => !f.Contains("/bin/", StringComparison.Ordinal) && !f.Contains("/obj/", StringComparison.Ordinal) && !f.Contains("/.git/", StringComparison.Ordinal))
            .Select(f => Path.GetRelativePath(root, f).Replace('\\', '/')).ToArray();
        var missing = new List<string>();

        foreach (Match m in CodeSpan().Matches(text))
        {
            string named = m.Groups[1].Value;
            bool isPath = named.StartsWith("src/", StringComparison.Ordinal) || named.StartsWith("tests/", StringComparison.Ordinal)
                || named.StartsWith("drivers/", StringComparison.Ordinal) || named.StartsWith("samples/", StringComparison.Ordinal);
            if (isPath && !named.Contains('*', StringComparison.Ordinal) && !named.Contains('<', StringComparison.Ordinal))
            {
                if (!files.Any(f => f == named || f.StartsWith(named.TrimEnd('/') + "/", StringComparison.Ordinal)))
                {
                    missing.Add(named);
                }
            }
            else if (named.EndsWith(".cs", StringComparison.Ordinal) && !named.Contains('*', StringComparison.Ordinal))
            {
                // A file named on its own or under its test folder, e.g. `KrlWriter.cs` or `Online/KukaOnlineTests.cs`.
                if (!files.Any(f => f.EndsWith("/" + named, StringComparison.Ordinal)))
                {
                    missing.Add(named);
                }
            }
        }

        Assert.True(missing.Count == 0, $"{Page} names files that do not exist: {string.Join(", ", missing)}");
    }

    [GeneratedRegex(@"`([^`\s]+)`")]
    private static partial Regex CodeSpan();
}

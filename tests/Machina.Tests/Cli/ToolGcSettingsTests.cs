using System.Text.Json;

namespace Machina.Tests.Cli;

/// <summary>
/// The machina tool caps the GC's first generation at 4 MB (Machina.Cli.csproj, <c>System.GC.Gen0MaxBudget</c>): left to
/// itself the GC sizes it from the processor's last-level cache, and on a machine with a 260 MiB L3 a compile of 10^6 lines
/// then peaked at 68-100 MB instead of 23-31 MB. The JIT tool takes the setting from its runtimeconfig.json (the native file
/// has the same item baked in as a runtime knob).
/// </summary>
public sealed class ToolGcSettingsTests
{
    [Fact]
    public void JitTool_RuntimeConfig_CapsTheFirstGenerationAtFourMegabytes()
    {
        // The referenced tool's runtimeconfig.json is copied beside the tests, as beside the tool itself.
        string path = Path.Combine(AppContext.BaseDirectory, "Machina.Cli.runtimeconfig.json");
        Assert.True(File.Exists(path), $"{path} is missing");
        using JsonDocument config = JsonDocument.Parse(File.ReadAllText(path));
        JsonElement properties = config.RootElement.GetProperty("runtimeOptions").GetProperty("configProperties");

        Assert.True(properties.TryGetProperty("System.GC.Gen0MaxBudget", out JsonElement budget), "System.GC.Gen0MaxBudget is not set");
        Assert.Equal(4L * 1024 * 1024, budget.GetInt64());
        // Tiered compilation stays off for the tool (a compile is a short process spent in a few hot loops).
        Assert.False(properties.GetProperty("System.Runtime.TieredCompilation").GetBoolean());
    }

    /// <summary>
    /// The thread pool's idle workers sleep at once instead of spinning for more work: `machina sim` gives the pool only a 50 ms
    /// timer item, after which the workers spun about 68 times each (docs/performance.md, session 29).
    /// </summary>
    [Fact]
    public void JitTool_RuntimeConfig_TurnsTheThreadPoolsSpinningOff()
    {
        string path = Path.Combine(AppContext.BaseDirectory, "Machina.Cli.runtimeconfig.json");
        Assert.True(File.Exists(path), $"{path} is missing");
        using JsonDocument config = JsonDocument.Parse(File.ReadAllText(path));
        JsonElement properties = config.RootElement.GetProperty("runtimeOptions").GetProperty("configProperties");

        Assert.True(properties.TryGetProperty("System.Threading.ThreadPool.UnfairSemaphoreSpinLimit", out JsonElement limit),
            "System.Threading.ThreadPool.UnfairSemaphoreSpinLimit is not set");
        Assert.Equal(0, limit.GetInt32());
    }
}

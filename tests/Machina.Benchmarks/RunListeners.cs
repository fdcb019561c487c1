namespace Machina.Benchmarks;

/// <summary>
/// The harness's in-process event listeners (<c>MACHINA_BENCH_JIT=1</c>: <see cref="JitMethods"/>; <c>MACHINA_BENCH_ALLOCS=1</c>:
/// <see cref="AllocationTypes"/>), made before the scenario's <see cref="Scenario.Prepare"/> starts any thread. An
/// <see cref="System.Diagnostics.Tracing.EventListener"/>'s constructor enables its events while holding the runtime's listener
/// lock, and enabling them starts a task, which runs the static constructor of the task library's event source; a twin's thread
/// whose first await ran that same constructor waited for the lock inside it: each waited for the other for good (the
/// `plain-abb` hangs of sessions 33-35, `MACHINA_BENCH_JIT=1`: the main thread in <c>JitMethods..ctor</c> ->
/// <c>Task.ScheduleAndStart</c>, <c>RAPID T_ROB1</c> in <c>TplEventSource..cctor</c> -> <c>EventListener.AddEventSource</c>).
/// Made first, on the only thread, they meet no other. They record around every run, warm-ups included; <see cref="Clear"/> forgets what the
/// warm-ups left.
/// </summary>
internal sealed class RunListeners(JitMethods? compiled, AllocationTypes? types) : IDisposable
{
    /// <summary>The methods compiled and exceptions thrown, when asked for.</summary>
    public JitMethods? Compiled { get; } = compiled;

    /// <summary>The allocations by type, when asked for.</summary>
    public AllocationTypes? Types { get; } = types;

    /// <summary>The listeners the environment asks for (none unless <c>MACHINA_BENCH_JIT=1</c> or <c>MACHINA_BENCH_ALLOCS=1</c>).</summary>
    public static RunListeners FromEnvironment() => new(
        Environment.GetEnvironmentVariable("MACHINA_BENCH_JIT") == "1" ? new JitMethods() : null,
        Environment.GetEnvironmentVariable("MACHINA_BENCH_ALLOCS") == "1" ? new AllocationTypes() : null);

    /// <summary>Starts or stops both recording: around each run's work, warm-ups included (so that their recording code is compiled before the measured runs).</summary>
    public void Count(bool on)
    {
        if (Compiled is not null)
        {
            Compiled.Counting = on;
        }
        if (Types is not null)
        {
            Types.Counting = on;
        }
    }

    /// <summary>Forgets what was recorded so far (the warm-ups'): what follows is the measured runs'.</summary>
    public void Clear()
    {
        Compiled?.Clear();
        Types?.Clear();
    }

    /// <inheritdoc/>
    public void Dispose()
    {
        Compiled?.Dispose();
        Types?.Dispose();
    }
}

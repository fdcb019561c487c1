namespace Machina.Benchmarks;

/// <summary>
/// What a scenario must reach, as a cost per unit of work (an action, a line, a pose) so that it scales with the size:
/// the time per unit at most <see cref="NanosecondsPerUnit"/>, and optionally the bytes allocated per unit at most
/// <see cref="BytesPerUnit"/>. <see cref="Text"/> states the target as the issue does.
/// </summary>
internal sealed record Target(double NanosecondsPerUnit, double? BytesPerUnit, string Text)
{
    /// <summary>True when the limit is on processor time per unit (the whole process, every thread), not wall time.</summary>
    public bool OnProcessorTime { get; init; }

    /// <summary>A processor-time limit per unit, e.g. 20 µs of CPU per streamed action, host and twin together.</summary>
    public static Target CpuMicroseconds(double microseconds, string text) => new(microseconds * 1e3, null, text) { OnProcessorTime = true };

    /// <summary>A time limit for a whole batch of <paramref name="units"/> units, e.g. 0.5 s for 1,000,000 moves.</summary>
    public static Target Seconds(double seconds, int units, string text, double? bytesPerUnit = null) =>
        new(seconds * 1e9 / units, bytesPerUnit, text);

    /// <summary>A throughput floor, e.g. at least 20,000 actions per second.</summary>
    public static Target PerSecond(double unitsPerSecond, string text) => new(1e9 / unitsPerSecond, null, text);

    /// <summary>A latency limit per unit, e.g. 5 µs per inverse kinematics call.</summary>
    public static Target Microseconds(double microseconds, string text) => new(microseconds * 1e3, null, text);
}

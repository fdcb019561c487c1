using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Benchmarks.Differential;

/// <summary>What the differential property found for one program on one brand.</summary>
internal enum DifferentialVerdict
{
    /// <summary>Both runs ended the program, through the same poses, joints and outputs.</summary>
    Finished,

    /// <summary>The controller stopped both runs after the same steps (an unreachable target, a joint limit).</summary>
    Stopped,

    /// <summary>The online pre-check found a target out of reach before anything moved, and the compiled program stopped on the twin.</summary>
    Unreachable,

    /// <summary>The online pre-check refused an action the driver cannot stream, before anything moved.</summary>
    Refused,

    /// <summary>The runs differ.</summary>
    Disagreed,
}

/// <summary>
/// The differential property on one program: compiled and run on the twin (<see cref="OfflineRun"/>), and streamed through our
/// driver to the same twin (<see cref="OnlineRun"/>); the two reach the same poses and joints (within 0.01 mm and 0.01°), set
/// the same outputs and end the same way, step by step.
/// </summary>
internal static class DifferentialCheck
{
    /// <summary>Largest position difference accepted between the two runs, mm.</summary>
    internal const double PositionToleranceMm = 0.01;

    /// <summary>Largest orientation or joint difference accepted between the two runs, degrees.</summary>
    internal const double AngleToleranceDegrees = 0.01;

    /// <summary>One program's outcome: the verdict, and for a disagreement or refusal what happened.</summary>
    internal sealed record Result(DifferentialVerdict Verdict, string Detail, TwinRun? Offline, TwinRun? Online)
    {
        /// <summary>For a refusal, the refused instruction's name (e.g. <c>ArcMotionTo</c>).</summary>
        internal string? Verb { get; init; }
    }

    /// <summary>Parses <paramref name="program"/> and runs both halves on <paramref name="brand"/>.</summary>
    internal static Task<Result> RunAsync(RobotType brand, string program, CancellationToken cancellation) =>
        RunAsync(brand, Instructions.Parse(program), cancellation);

    /// <summary>Runs both halves of <paramref name="actions"/> on <paramref name="brand"/>.</summary>
    internal static async Task<Result> RunAsync(RobotType brand, IReadOnlyList<RobotAction> actions, CancellationToken cancellation)
    {
        Joints start = OfflineRun.StartOf(brand, actions);
        TwinRun offline = OfflineRun.Run(brand, actions, start, cancellation);
        TwinRun online = await OnlineRun.RunAsync(brand, actions, start, cancellation).ConfigureAwait(false);
        return Compare(brand, actions, offline, online);
    }

    /// <summary>The verdict on two runs of <paramref name="actions"/>.</summary>
    internal static Result Compare(RobotType brand, IReadOnlyList<RobotAction> actions, TwinRun offline, TwinRun online)
    {
        string At(int? i) => i is int k && k < actions.Count ? $"action {k + 1} ({actions[k].ToInstruction()})" : "an action";
        switch (online.End)
        {
            case TwinRunEnd.Refused:
                return online.Steps.Count == 0
                    ? new Result(DifferentialVerdict.Refused, $"{At(online.Action)}: {online.Why}", offline, online)
                    {
                        Verb = online.Action is int r && r < actions.Count ? actions[r].ToInstruction().Split('(')[0] : null,
                    }
                    : new Result(DifferentialVerdict.Disagreed, $"refused at {At(online.Action)} after the arm moved: {online.Why}", offline, online);
            case TwinRunEnd.Unreachable:
                return offline.End == TwinRunEnd.Stopped
                    ? new Result(DifferentialVerdict.Unreachable, $"{At(online.Action)}: {online.Why}; offline: {offline.Why}", offline, online)
                    : new Result(DifferentialVerdict.Disagreed, $"the pre-check finds {At(online.Action)} out of reach ({online.Why}), but the compiled program runs to its end", offline, online);
        }
        if (offline.End != online.End)
        {
            return new Result(DifferentialVerdict.Disagreed, offline.End == TwinRunEnd.Finished
                ? $"the compiled program runs to its end; streamed, it stops at {At(online.Action)}: {online.Why}"
                : $"streamed, the program runs to its end; compiled, the twin stops it: {offline.Why}", offline, online);
        }
        if (FirstDifference(offline.Steps, online.Steps, (PositionToleranceMm, AngleToleranceDegrees)) is string difference)
        {
            // Every brand to 0.01 mm and 0.01°: UR's driver carries 0.001 mm and 1e-6 rad since 3.0 (its 0.1 mm and 1e-4 rad were counted apart before).
            return new Result(DifferentialVerdict.Disagreed, difference, offline, online);
        }
        return offline.End == TwinRunEnd.Finished
            ? new Result(DifferentialVerdict.Finished, "", offline, online)
            : new Result(DifferentialVerdict.Stopped, $"offline: {offline.Why}; online: {At(online.Action)}: {online.Why}", offline, online);
    }

    /// <summary>The first step where the two traces differ, described, or null.</summary>
    internal static string? FirstDifference(IReadOnlyList<TwinTraceEntry> offline, IReadOnlyList<TwinTraceEntry> online, (double Mm, double Degrees) tolerance)
    {
        for (int i = 0; i < Math.Max(offline.Count, online.Count); i++)
        {
            if (i >= offline.Count || i >= online.Count)
            {
                return $"step {i + 1}: {(i >= offline.Count ? "only streamed" : "only compiled")}: {Describe(i >= offline.Count ? online[i] : offline[i])}";
            }
            TwinTraceEntry a = offline[i], b = online[i];
            if (Differs(a, b, tolerance) is string why)
            {
                return $"step {i + 1}: {why}; compiled: {Describe(a)}; streamed: {Describe(b)}";
            }
        }
        return null;
    }

    private static string? Differs(TwinTraceEntry a, TwinTraceEntry b, (double Mm, double Degrees) tolerance)
    {
        if (a.Kind != b.Kind)
        {
            return "one is a motion, the other an output";
        }
        if (a.Kind == TwinTraceKind.Output)
        {
            return a.Text.Equals(b.Text, StringComparison.OrdinalIgnoreCase) ? null : "the outputs differ";
        }
        double mm = (a.Tcp.Position - b.Tcp.Position).Length;
        double degrees = TwinRotation.AngleDegrees(a.Tcp.Rotation, b.Tcp.Rotation);
        double joints = (a.Joints - b.Joints).ToArray().Max(Math.Abs);
        if (mm <= tolerance.Mm && degrees <= tolerance.Degrees && joints <= tolerance.Degrees)
        {
            return null;
        }
        return string.Create(CultureInfo.InvariantCulture, $"the TCP is {mm:0.####} mm and {degrees:0.####}° apart, the joints up to {joints:0.####}°");
    }

    private static string Describe(TwinTraceEntry e) => e.Kind == TwinTraceKind.Output
        ? $"line {e.Line} {e.Text}"
        : $"line {e.Line} {e.Text}: TCP {e.Tcp.Position} {e.Tcp.Rotation.ToQuaternionString()}, joints {e.Joints}";
}

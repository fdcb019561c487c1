using System.Globalization;

namespace Machina.Cli.Programs;

/// <summary>A program's estimated cycle time as <c>check</c> and <c>preview</c> tell it: motions and waits, and what could not be timed.</summary>
internal sealed class CycleTime
{
    /// <summary>Seconds of motion (applied motions that could be timed).</summary>
    internal double MotionSeconds { get; private set; }

    /// <summary>Seconds of waiting (<c>Wait</c> actions).</summary>
    internal double WaitSeconds { get; private set; }

    /// <summary>Applied motions left out because their pose or joints were not known.</summary>
    internal int Untimed { get; private set; }

    /// <summary>Adds what one tried step takes.</summary>
    internal void Add(TrialStep step)
    {
        if (!step.Applied)
        {
            return;
        }
        if (step.Duration is not TimeSpan duration)
        {
            Untimed++;
        }
        else if (step.Action is ActionWait)
        {
            WaitSeconds += duration.TotalSeconds;
        }
        else
        {
            MotionSeconds += duration.TotalSeconds;
        }
    }

    /// <summary>Seconds in all.</summary>
    internal double TotalSeconds => MotionSeconds + WaitSeconds;

    /// <summary>The total in a few characters, e.g. "12.4 s" or "3 min 05.2 s".</summary>
    internal static string Short(double seconds) => seconds < 60
        ? seconds.ToString(seconds < 10 ? "0.00" : "0.0", CultureInfo.InvariantCulture) + " s"
        : string.Create(CultureInfo.InvariantCulture, $"{Math.Floor(seconds / 60):0} min {seconds % 60:00.0} s");

    /// <summary>
    /// The line both commands print, naming whose controller timed it; for a controller whose blends are not modelled
    /// (<paramref name="model"/>'s brand, or none) it says that blended paths were timed as exact ones.
    /// </summary>
    internal string ToText(string controller, RobotModel? model)
    {
        string blends = ProgramTrial.TimingOf(model).NewBlendTiming() is null ? "; blends not shortened" : "";
        string text = $"Estimated cycle time on {controller}: {Short(TotalSeconds)} (motion {Short(MotionSeconds)}, waits {Short(WaitSeconds)}{blends})";
        return Untimed == 0 ? text + "."
            : text + $"; {Untimed} motion{(Untimed == 1 ? "" : "s")} not timed: where {(Untimed == 1 ? "it starts" : "they start")} is not known (before the first absolute position, or joints without a --model).";
    }
}

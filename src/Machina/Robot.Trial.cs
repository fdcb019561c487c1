namespace Machina;

public sealed partial class Robot
{
    /// <summary>
    /// A dry run from the state the next issued action starts from (pose, settings, tools, the arm model): try a program's actions
    /// on it to learn what this robot would refuse (online: also what its brand's driver cannot run) and what its arm cannot reach,
    /// before anything is issued. The robot itself is not changed.
    /// </summary>
    public ProgramTrial StartTrial()
    {
        lock (_issueLock)
        {
            MotionTiming timing = BrandRegistry.For(Brand).Timing;
            return new ProgramTrial(_issueCursor, _session, timing == MotionTiming.Generic ? ProgramTrial.TimingOf(_issueCursor.Model) : timing);
        }
    }
}

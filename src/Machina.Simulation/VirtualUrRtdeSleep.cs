using System.Runtime.InteropServices;

namespace Machina.Simulation;

/// <summary>
/// The last stretch of the RTDE sender's wait on Linux: a sleep of the operating system to the microsecond. .NET's timed waits
/// count whole milliseconds, so a sender that waits with them sends each package up to half a millisecond either side of its
/// deadline and its period error reaches a millisecond on an idle machine (issue 45: p99 0.952 ms alone at 500 Hz); a
/// <c>clock_nanosleep</c> of the monotonic clock ends within the timer slack of the deadline, which the sender's thread sets to
/// a microsecond (<c>prctl(PR_SET_TIMERSLACK)</c>; Linux's default is 50 µs). Neither spins. Elsewhere, or when the C library
/// does not have them, <see cref="Available"/> is false and the sender keeps its millisecond waits.
/// </summary>
internal static class VirtualUrRtdeSleep
{
    private const int ClockMonotonic = 1, PrSetTimerSlack = 29;

    /// <summary>True on Linux, where the sleep below is used.</summary>
    public static bool Available => OperatingSystem.IsLinux();

    /// <summary>Asks for a timer slack of one microsecond for the calling thread (its sleeps end that close to their time); false when refused.</summary>
    public static bool TightenTimerSlack()
    {
        try
        {
            return Available && prctl(PrSetTimerSlack, 1000, 0, 0, 0) == 0;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return false;
        }
    }

    /// <summary>
    /// Sleeps <paramref name="nanoseconds"/> on the monotonic clock (a signal may end it early: the caller looks at the clock
    /// again); false when the system has no such sleep (the caller waits its own way).
    /// </summary>
    public static bool Sleep(long nanoseconds)
    {
        var request = new TimeSpec { Seconds = (nint)(nanoseconds / 1_000_000_000), Nanoseconds = (nint)(nanoseconds % 1_000_000_000) };
        try
        {
            _ = clock_nanosleep(ClockMonotonic, 0, in request, IntPtr.Zero);
            return true;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return false;
        }
    }

    /// <summary>struct timespec: time_t and long, both the platform's word on Linux.</summary>
    [StructLayout(LayoutKind.Sequential)]
    private struct TimeSpec
    {
        public nint Seconds;
        public nint Nanoseconds;
    }

    [DllImport("libc", EntryPoint = "clock_nanosleep")]
    private static extern int clock_nanosleep(int clock, int flags, in TimeSpec request, IntPtr remaining);

    [DllImport("libc", EntryPoint = "prctl")]
    private static extern int prctl(int option, nuint value, nuint unused2, nuint unused3, nuint unused4);
}

using System.Runtime.InteropServices;

namespace Machina.Simulation;

/// <summary>
/// The RTDE sender thread's share of the processor on Linux: a short time slice. Since Linux 6.12 (EEVDF) any thread may ask
/// for its own slice (<c>sched_setattr</c> with its policy and nice unchanged and <c>sched_runtime</c> set: no privilege, no
/// higher priority, the same share of the processor), and a woken thread whose slice is shorter than the running one's takes
/// the processor at once instead of waiting for that thread's slice to end (the kernel's PREEMPT_SHORT): on two cores kept busy
/// by a stream (the twin's program thread and the host), the sender woken at a package's deadline otherwise waited up to the
/// running thread's slice (about 1.5 ms on two cores) for a core, which was the p99 of the period beside a stream (issue 45).
/// Older kernels take the call and ignore the slice; elsewhere nothing is asked.
/// </summary>
internal static class VirtualUrRtdeSlice
{
    /// <summary>The slice asked for: 100 µs, the shortest Linux grants (a package takes a few tens of microseconds to send).</summary>
    internal const long SliceNanoseconds = 100_000;

    private const int PrioProcess = 0;

    /// <summary>Asks for a short slice for the calling thread; false when not on Linux or refused.</summary>
    public static bool Shorten()
    {
        long number = RuntimeInformation.ProcessArchitecture switch
        {
            Architecture.X64 => 314,
            Architecture.Arm64 => 274,
            _ => -1,
        };
        if (!OperatingSystem.IsLinux() || number < 0)
        {
            return false;
        }
        try
        {
            // The thread's own nice value, unchanged (lowering it would need a privilege): getpriority of the calling thread.
            int nice = getpriority(PrioProcess, 0);
            var attr = new SchedAttr
            {
                Size = (uint)Marshal.SizeOf<SchedAttr>(),
                Policy = 0, // SCHED_OTHER
                Nice = Math.Clamp(nice, -20, 19),
                Runtime = SliceNanoseconds,
            };
            return syscall(number, 0, ref attr, 0) == 0;
        }
        catch (Exception e) when (e is DllNotFoundException or EntryPointNotFoundException)
        {
            return false;
        }
    }

    /// <summary>struct sched_attr, its first version (48 bytes).</summary>
    [StructLayout(LayoutKind.Sequential)]
    private struct SchedAttr
    {
        public uint Size;
        public uint Policy;
        public ulong Flags;
        public int Nice;
        public uint Priority;
        public long Runtime;
        public long Deadline;
        public long Period;
    }

    [DllImport("libc", EntryPoint = "syscall")]
    private static extern long syscall(long number, int pid, ref SchedAttr attr, uint flags);

    [DllImport("libc", EntryPoint = "getpriority")]
    private static extern int getpriority(int which, uint who);
}

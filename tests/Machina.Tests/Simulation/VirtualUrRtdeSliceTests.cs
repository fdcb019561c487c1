using System.Runtime.InteropServices;
using Machina.Simulation;

namespace Machina.Tests.Simulation;

/// <summary>The RTDE sender's short time slice on Linux (issue 45: woken at a deadline, it takes a busy core at once).</summary>
public class VirtualUrRtdeSliceTests
{
    [Fact]
    public void OnLinux_TheSenderThreadGetsAShortSlice_AndKeepsItsPolicyAndNice()
    {
        if (!OperatingSystem.IsLinux() || RuntimeInformation.ProcessArchitecture is not (Architecture.X64 or Architecture.Arm64))
        {
            Assert.False(VirtualUrRtdeSlice.Shorten()); // nothing is asked elsewhere
            return;
        }
        bool shortened = false;
        string before = "", after = "";
        // A thread of its own: the slice stays with the thread that asked.
        var thread = new Thread(() =>
        {
            before = File.ReadAllText("/proc/thread-self/sched");
            shortened = VirtualUrRtdeSlice.Shorten();
            after = File.ReadAllText("/proc/thread-self/sched");
        });
        thread.Start();
        Assert.True(thread.Join(TimeSpan.FromSeconds(10)));
        Assert.True(shortened, "sched_setattr refused the sender's slice");
        Assert.Equal(Field(before, "policy"), Field(after, "policy"));
        Assert.Equal(Field(before, "prio"), Field(after, "prio"));
        // Kernels before 6.12 take the call and keep their own slice; those that show it must show the one asked for.
        if (Field(after, "se.custom_slice") == "1" || (Field(after, "se.slice") is not null && Environment.OSVersion.Version >= new Version(6, 12)))
        {
            Assert.Equal(VirtualUrRtdeSlice.SliceNanoseconds.ToString(System.Globalization.CultureInfo.InvariantCulture), Field(after, "se.slice"));
        }
    }

    /// <summary>A "name : value" line of /proc/thread-self/sched, or null.</summary>
    private static string? Field(string sched, string name)
    {
        foreach (string line in sched.Split('\n'))
        {
            string[] parts = line.Split(':', 2);
            if (parts.Length == 2 && parts[0].Trim() == name)
            {
                return parts[1].Trim();
            }
        }
        return null;
    }
}

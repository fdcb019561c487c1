using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>The benchmarks' processor time by thread: differences are taken per thread id, then summed per name.</summary>
public class ThreadCpuTests
{
    [Fact]
    public void Difference_ANewThreadReplacesAnEndedOneOfTheSameName_CountsTheNewOnesTime()
    {
        // A run disconnects the last run's robot (its link thread ends) and connects a new one (a new link thread, same name).
        var before = new Dictionary<int, ThreadCpu.ThreadTime>
        {
            [1] = new("dotnet", 2.0, 10),
            [7] = new("Machina link", 1.0, 900),
        };
        var after = new Dictionary<int, ThreadCpu.ThreadTime>
        {
            [1] = new("dotnet", 2.5, 12),
            [9] = new("Machina link", 0.25, 300),
            [10] = new(ThreadCpu.JitThreadName, 0.13, 40),
        };

        List<ThreadCpu.ThreadTime> difference = ThreadCpu.Difference(before, after);

        Assert.Equal([new("dotnet", 0.5, 2), new("Machina link", 0.25, 300), new(ThreadCpu.JitThreadName, 0.13, 40)], difference);
        Assert.Equal(0.13, ThreadCpu.Jit(difference));
        Assert.Equal("dotnet 0.500 s (5000.0 us, 0.02 runs/unit), Machina link 0.250 s (2500.0 us, 3.00 runs/unit), .NET Tiered Com 0.130 s (1300.0 us, 0.40 runs/unit)",
            ThreadCpu.Text(difference, 100));
    }

    [Fact]
    public void Read_ThisProcess_SeesThisThreadRunning()
    {
        if (!Directory.Exists("/proc/self/task"))
        {
            return;   // Linux only
        }
        Dictionary<int, ThreadCpu.ThreadTime> threads = ThreadCpu.Read();
        Assert.Contains(threads.Values, t => t.Seconds > 0 && t.Slices > 0);
    }
}

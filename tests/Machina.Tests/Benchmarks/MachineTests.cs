using Machina.Benchmarks;

namespace Machina.Tests.Benchmarks;

/// <summary>What the benchmarks read of the machine and of their own process.</summary>
public class MachineTests
{
    [Fact]
    public void MinorPageFaults_IsField10OfProcSelfStat_BetweenTwoReadsOfTheWholeFile()
    {
        if (!File.Exists("/proc/self/stat"))
        {
            return;   // Linux only
        }
        static long ByFields() => long.Parse(Machine.StatFields("/proc/self/stat")![7], System.Globalization.CultureInfo.InvariantCulture);
        _ = Machine.MinorPageFaults(); // its own first faults (code, stack) before the bracket

        long before = ByFields();
        long read = Machine.MinorPageFaults();
        long after = ByFields();

        Assert.True(before > 0, $"minflt {before}");
        Assert.InRange(read, before, after);
    }
}

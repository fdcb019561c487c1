using Machina.Simulation.Krl;

namespace Machina.Tests.Simulation.Krl;

/// <summary>An EthernetKRL value memory (a ring of strings): FIFO and LIFO order kept across the ring's end and while it grows.</summary>
public class EkiMemoryTests
{
    [Fact]
    public void AddAndTake_AcrossTheRingsEndAndGrowth_FifoOldestFirstLifoNewestFirst()
    {
        var memory = new EkiMemory();
        var model = new List<string>();
        int next = 0;
        var taken = new List<string>();
        var expected = new List<string>();
        // Rounds that add more than they take: the ring wraps (its first element moves on) and doubles several times.
        for (int round = 0; round < 40; round++)
        {
            for (int i = 0; i < 7; i++)
            {
                string value = (next++).ToString(System.Globalization.CultureInfo.InvariantCulture);
                memory.AddLast(value);
                model.Add(value);
            }
            for (int i = 0; i < 4; i++)
            {
                bool fifo = (round + i) % 3 != 0;
                taken.Add(fifo ? memory.TakeFirst() : memory.TakeLast());
                expected.Add(fifo ? model[0] : model[^1]);
                model.RemoveAt(fifo ? 0 : model.Count - 1);
            }
            Assert.Equal(model.Count, memory.Count);
        }
        Assert.Equal(expected, taken);
        memory.Clear();
        Assert.Equal(0, memory.Count);
        memory.AddLast("x");
        Assert.Equal("x", memory.TakeLast());
    }
}

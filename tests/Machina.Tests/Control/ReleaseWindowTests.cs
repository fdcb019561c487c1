namespace Machina.Tests.Control;

public class ReleaseWindowTests
{
    [Theory]
    [InlineData(0, 30, 0, 8, 0)]  // nothing on the device: a full block
    [InlineData(2, 30, 0, 8, 0)]  // 2 left (< 3): refill
    [InlineData(3, 30, 0, 0, 0)]  // 3 left and the block is used up: wait
    [InlineData(3, 30, 5, 5, 0)]  // 3 left but the open block has 5 more: release them
    [InlineData(0, 5, 0, 5, 3)]   // fewer buffered than a block: release what there is, the block stays open
    [InlineData(1, 0, 0, 0, 8)]   // nothing buffered: the block opens and waits
    [InlineData(1, 30, 2, 2, 0)]  // the open block is finished before a new one opens
    public void Take_Defaults_BlocksOfEightWhenFewerThanThreeRemain(int unexecuted, int buffered, int credit, int expected, int creditAfter)
    {
        Assert.Equal(expected, new ReleaseWindow().Take(unexecuted, buffered, ref credit));
        Assert.Equal(creditAfter, credit);
    }

    [Fact]
    public void Defaults_KeepAtMostTenOnTheDeviceLikeTheOriginal()
    {
        var w = new ReleaseWindow();
        Assert.Equal(8, w.BlockSize);
        Assert.Equal(3, w.PendingCount);
        Assert.Equal(10, (w.PendingCount - 1) + w.BlockSize);
    }

    [Theory]
    [InlineData(0)]
    [InlineData(-4)]
    public void BlockSize_NotPositive_ThrowsNamingTheSetting(int value)
    {
        var ex = Assert.Throws<ArgumentOutOfRangeException>(() => new ReleaseWindow().BlockSize = value);
        Assert.Equal("blockSize", ex.ParamName);
        Assert.Contains("block size must be 1 or more", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void StreamConfiguration_OriginalMinMax_MapsToBlockAndPending()
    {
        var bot = Robot.Create("Cfg", "ABB");
        Assert.True(bot.StreamConfiguration(4, 12));
        Assert.Equal(8, bot.BlockSize);
        Assert.Equal(5, bot.PendingCount);
        Assert.Throws<ArgumentOutOfRangeException>(() => bot.StreamConfiguration(5, 5));
        Assert.Throws<ArgumentOutOfRangeException>(() => bot.StreamConfiguration(-1, 5));
        Assert.Equal(8, bot.BlockSize);
    }
}

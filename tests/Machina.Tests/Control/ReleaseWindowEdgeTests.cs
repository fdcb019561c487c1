namespace Machina.Tests.Control;

/// <summary>The release window's settings and its arithmetic at the edges (the gaps mutation testing found), with exact values and messages.</summary>
public class ReleaseWindowEdgeTests
{
    [Theory]
    [InlineData(0, "The pending count must be 1 or more; 0 was given.")]
    [InlineData(-7, "The pending count must be 1 or more; -7 was given.")]
    public void PendingCount_NotPositive_RefusedWithTheSettingAndValue_KeepsTheOldValue(int value, string message)
    {
        var window = new ReleaseWindow { PendingCount = 4 };
        ArgumentOutOfRangeException e = Assert.Throws<ArgumentOutOfRangeException>(() => window.PendingCount = value);
        Assert.Equal("pendingCount", e.ParamName);
        Assert.Equal(value, e.ActualValue);
        Assert.StartsWith(message, e.Message, StringComparison.Ordinal);
        Assert.Equal(4, window.PendingCount);
    }

    [Fact]
    public void BlockSize_Zero_RefusedWithTheExactMessage_KeepsTheOldValue()
    {
        var window = new ReleaseWindow { BlockSize = 6 };
        ArgumentOutOfRangeException e = Assert.Throws<ArgumentOutOfRangeException>(() => window.BlockSize = 0);
        Assert.Equal(0, e.ActualValue);
        Assert.StartsWith("The block size must be 1 or more; 0 was given.", e.Message, StringComparison.Ordinal);
        Assert.Equal(6, window.BlockSize);
    }

    [Fact]
    public void OneIsTheSmallestSetting_BlocksOfOneWhenNothingIsLeft()
    {
        var window = new ReleaseWindow { BlockSize = 1, PendingCount = 1 };
        Assert.Equal((1, 1), (window.BlockSize, window.PendingCount));
        int credit = 0;
        Assert.Equal(1, window.Take(0, 5, ref credit));
        Assert.Equal(0, credit);
        Assert.Equal(0, window.Take(1, 4, ref credit)); // one unexecuted is not fewer than 1
        Assert.Equal(0, credit);
        Assert.Equal(1, window.Take(0, 4, ref credit));
    }

    [Theory]
    [InlineData(4, 0, 3)]  // pending count 5: 4 unexecuted is fewer, a block opens
    [InlineData(5, 0, 0)]  // 5 is not fewer than 5: wait
    [InlineData(6, 0, 0)]
    public void Take_CustomPendingCount_OpensBelowIt(int unexecuted, int credit, int expected)
    {
        var window = new ReleaseWindow { BlockSize = 3, PendingCount = 5 };
        Assert.Equal(expected, window.Take(unexecuted, 10, ref credit));
        Assert.Equal(0, credit);
    }

    [Fact]
    public void Take_BlockSizeLoweredWhileABlockIsOpen_TheOpenBlockShrinksToIt()
    {
        var window = new ReleaseWindow(); // blocks of 8
        int credit = 0;
        Assert.Equal(2, window.Take(0, 2, ref credit));
        Assert.Equal(6, credit);
        window.BlockSize = 4;
        Assert.Equal(4, window.Take(5, 30, ref credit)); // 6 left in the block, but no more than a block of 4
        Assert.Equal(0, credit);
    }

    [Fact]
    public void Take_BlockSizeRaisedWhileABlockIsOpen_TheOpenBlockKeepsItsCredit()
    {
        var window = new ReleaseWindow { BlockSize = 4 };
        int credit = 0;
        Assert.Equal(1, window.Take(0, 1, ref credit));
        Assert.Equal(3, credit);
        window.BlockSize = 20;
        Assert.Equal(2, window.Take(0, 2, ref credit)); // credit 3 is not 0: the open block continues, no new block of 20
        Assert.Equal(1, credit);
    }
}

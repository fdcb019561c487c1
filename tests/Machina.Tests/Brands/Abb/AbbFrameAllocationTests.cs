namespace Machina.Tests.Brands.Abb;

/// <summary>Encoding a streamed action for the ABB driver allocates its frame and nothing else (no list of requests, no array of them).</summary>
public class AbbFrameAllocationTests
{
    [Fact]
    public void Encode_AMove_AllocatesOnlyTheFrame_SameBytesAsTheRequests()
    {
        var brand = new AbbOnline();
        var cursor = new RobotCursor();
        var action = new ActionTransformation(new Vector(400, 0, 500), Rotation.FromQuaternion(0, 0, 1, 0), false, true) { Id = 7 };
        Assert.Null(cursor.TryApply(action));
        brand.Encode(action, cursor, out _);   // compiled once

        long before = GC.GetAllocatedBytesForCurrentThread();
        ActionFrame frame = brand.Encode(action, cursor, out string? refusal);
        long allocated = GC.GetAllocatedBytesForCurrentThread() - before;

        Assert.Null(refusal);
        Assert.True(frame.Acknowledged);
        Assert.Equal("@7 1 400 0 500 0 0 1 0;", System.Text.Encoding.ASCII.GetString(frame.Bytes));
        // The frame and its bytes (about 100 bytes); the list of two requests it used to fill cost about 280 more.
        Assert.True(allocated < 160, $"{allocated} bytes allocated");
    }
}

using Machina.Simulation.UrScript;

namespace Machina.Tests.Simulation.UrScript;

/// <summary>
/// A thread's argument and local arrays are used again once their call has returned: an array given back comes back empty, calls
/// nested in one expression each get their own, and arrays too long to keep are simply new ones.
/// </summary>
public class UrScratchTests
{
    [Fact]
    public void ArrayGivenBack_IsUsedAgain_WithItsSlotsEmptied()
    {
        var scratch = new UrScratch();
        object?[] first = scratch.Rent(5);
        first[0] = "pose";
        first[4] = 0.25;
        scratch.Return(first);
        object?[] again = scratch.Rent(5);
        Assert.Same(first, again);
        Assert.All(again, slot => Assert.Null(slot));
        Assert.Equal(5, scratch.Rent(5).Length);
        Assert.NotSame(again, scratch.Rent(5));
    }

    [Fact]
    public void NestedCalls_EachHaveTheirOwnArray()
    {
        // movel(pose_of(read_ints(6)), a=…): the outer call's array is held while the inner ones are rented and given back.
        var scratch = new UrScratch();
        object?[] outer = scratch.Rent(3);
        object?[] inner = scratch.Rent(3);
        Assert.NotSame(outer, inner);
        scratch.Return(inner);
        object?[] innerAgain = scratch.Rent(3);
        Assert.Same(inner, innerAgain);
        Assert.NotSame(outer, innerAgain);
        Assert.Equal(2, scratch.Rent(2).Length);
    }

    [Fact]
    public void EmptyAndLongArrays_AreNotKept()
    {
        var scratch = new UrScratch();
        Assert.Empty(scratch.Rent(0));
        object?[] longOne = scratch.Rent(40);
        Assert.Equal(40, longOne.Length);
        scratch.Return(longOne);
        Assert.NotSame(longOne, scratch.Rent(40));
    }

    [Fact]
    public void AProgramsCalls_ReadTheirOwnArguments()
    {
        // Nested built-ins and functions of the program, each with arrays of the same length, and a function's locals after a call
        // that gave its arrays back: every value is the one its call was given.
        using var twin = new UrTwinController();
        UrProgramState state = twin.Run("""
            def prog():
              def f(x, y):
                z = str_cat(x, "-")
                return str_cat(z, y)
              end
              a = f(str_cat("a", "b"), f(str_cat("c", "d"), str_cat("e", "f")))
              textmsg(a, f("x", "y"))
            end
            """, CancellationToken.None);
        Assert.True(state == UrProgramState.Finished, twin.Error);
        Assert.Equal(["ab-cd-efx-y"], twin.Pendant.Lines);
    }
}

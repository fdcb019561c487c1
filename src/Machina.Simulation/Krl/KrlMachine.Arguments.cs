using System.Runtime.CompilerServices;

namespace Machina.Simulation.Krl;

/// <summary>
/// The argument arrays and OUT places of the calls under way, reused from call to call: calls nest (an argument's own call, an
/// interrupt routine, a routine's body all end before the call around them), so each call takes the next free array of its
/// length and the next free place box, and gives them back when it ends. The driver's 15 calls an action made 15 arrays and 11
/// boxed places (1.7 KB); a routine or built-in that kept an argument array or place box after its call would see it change,
/// and none does (a place is unboxed into a copy, the values are copied into the routine's frame).
/// </summary>
internal sealed partial class KrlMachine
{
    /// <summary>Calls with more arguments than this get an array of their own each time.</summary>
    private const int PooledArity = 8;

    /// <summary>Arrays (of one length) or place boxes kept at most: deeper nesting allocates as before.</summary>
    private const int PooledDepth = 256;

    /// <summary>For each argument count, the arrays of the calls under way (below its top) and free ones (from it).</summary>
    private readonly object[][]?[] _argumentArrays = new object[][]?[PooledArity + 1];
    private readonly int[] _argumentTops = new int[PooledArity + 1];
    private object[] _placeBoxes = new object[8];
    private int _placeTop;

    /// <summary>Where a call's borrowings start: what <see cref="GiveBack"/> returns to when the call ends.</summary>
    private readonly record struct Borrowed(int Count, int ArrayTop, int PlaceTop);

    /// <summary>An array of <paramref name="count"/> arguments for a call that starts now, and the mark to give it back at.</summary>
    private object[] BorrowArguments(int count, out Borrowed mark)
    {
        if (count == 0 || count > PooledArity)
        {
            mark = new Borrowed(0, 0, _placeTop);
            return count == 0 ? [] : new object[count];
        }
        int top = _argumentTops[count];
        mark = new Borrowed(count, top, _placeTop);
        object[][] arrays = _argumentArrays[count] ??= new object[4][];
        if (top == arrays.Length)
        {
            if (top >= PooledDepth)
            {
                return new object[count];
            }
            Array.Resize(ref arrays, top * 2);
            _argumentArrays[count] = arrays;
        }
        _argumentTops[count] = top + 1;
        return arrays[top] ??= new object[count];
    }

    /// <summary>A box holding <paramref name="place"/> for an OUT argument of the call under way (see <see cref="BorrowArguments"/>).</summary>
    private object BoxPlace(in KrlPlace place)
    {
        if (_placeTop == _placeBoxes.Length)
        {
            if (_placeTop >= PooledDepth)
            {
                return place;
            }
            Array.Resize(ref _placeBoxes, _placeTop * 2);
        }
        object box = _placeBoxes[_placeTop] ??= default(KrlPlace);
        Unsafe.Unbox<KrlPlace>(box) = place;
        _placeTop++;
        return box;
    }

    /// <summary>The call that borrowed at <paramref name="mark"/> ended: its array and place boxes (and its nested calls') are free.</summary>
    private void GiveBack(in Borrowed mark)
    {
        if (mark.Count > 0)
        {
            _argumentTops[mark.Count] = mark.ArrayTop;
        }
        _placeTop = mark.PlaceTop;
    }
}

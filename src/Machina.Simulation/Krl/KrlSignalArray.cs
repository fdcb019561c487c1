using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>
/// An IO system array of the KRL twin (<c>$IN</c>, <c>$OUT</c>: BOOL; <c>$ANIN</c>, <c>$ANOUT</c>: REAL) whose values are the
/// <see cref="TwinIo"/> bank of the same name: a program reads and writes its elements there, and the host sets the inputs and
/// reads the outputs there, as it does on the other twins.
/// </summary>
internal sealed class KrlSignalArray
{
    private readonly TwinIo _io;
    private readonly bool _digital;

    /// <summary>Declares the bank <paramref name="name"/> of <paramref name="count"/> signals in <paramref name="io"/> (all FALSE or 0).</summary>
    public KrlSignalArray(TwinIo io, string name, KrlType element, int count)
    {
        _io = io;
        _digital = element.Kind == KrlKind.Bool;
        Name = name;
        Type = KrlType.Array(element, count);
        if (_digital)
        {
            io.AddBits(name, count);
        }
        else
        {
            io.AddNumbers(name, count);
        }
    }

    /// <summary>The system variable's name, which is also its bank's name in <see cref="TwinIo"/>.</summary>
    public string Name { get; }

    /// <summary>The array type (<c>BOOL[n]</c> or <c>REAL[n]</c>).</summary>
    public KrlType Type { get; }

    /// <summary>Element <paramref name="index"/> (0-based) as a KRL value.</summary>
    public object Get(int index) => _digital ? KrlValues.Box(_io.GetBit(Name, index)) : _io.GetNumber(Name, index);

    /// <summary>Stores <paramref name="value"/> (converted to the element type) in element <paramref name="index"/> (0-based).</summary>
    public void Set(int index, object value)
    {
        object converted = KrlConvert.To(Type.Element!, value, null);
        if (_digital)
        {
            _io.SetBit(Name, index, (bool)converted);
        }
        else
        {
            _io.SetNumber(Name, index, (double)converted);
        }
    }

    /// <summary>The whole array as a KRL value (a copy: what a program reads as <c>$OUT</c>).</summary>
    public KrlArrayValue Get()
    {
        var items = new object[Type.Length];
        for (int i = 0; i < items.Length; i++)
        {
            items[i] = Get(i);
        }
        return new KrlArrayValue(Type, items);
    }

    /// <summary>Stores a whole array (converted to the array type, as an assignment to the variable does).</summary>
    public void Set(object value)
    {
        var items = (KrlArrayValue)KrlConvert.To(Type, value, null);
        for (int i = 0; i < items.Length; i++)
        {
            Set(i, items[i]);
        }
    }
}

using System.Runtime.CompilerServices;

namespace Machina.Simulation.Krl;

/// <summary>
/// An array value: its type and its elements (row by row for 2 and 3 dimensions), read and written through this value's indexer
/// (<c>a[i]</c>) or, for a REAL array, through <see cref="Real"/> and <see cref="SetReal"/>. A REAL array (the driver's
/// <c>slot_v</c>, <c>$SOFTN_END</c>, the analog IO) holds its elements unboxed, as doubles: a REAL stored there allocates nothing.
/// Other arrays hold their elements as objects (<see cref="Objects"/>).
/// </summary>
internal sealed class KrlArrayValue
{
    /// <summary>The elements: a <c>double[]</c> for a REAL array (<see cref="_reals"/>), else an <c>object[]</c>.</summary>
    private readonly object _store;

    /// <summary>True when <see cref="_store"/> is a <c>double[]</c>.</summary>
    private readonly bool _reals;

    /// <summary>An array of <paramref name="type"/> with the elements <paramref name="items"/> (a REAL array takes their values as doubles).</summary>
    public KrlArrayValue(KrlType type, object[] items)
    {
        Type = type;
        if (type.Element!.Kind == KrlKind.Real)
        {
            var reals = new double[items.Length];
            for (int i = 0; i < reals.Length; i++)
            {
                reals[i] = KrlValues.ToReal(items[i]);
            }
            _store = reals;
            _reals = true;
        }
        else
        {
            _store = items;
        }
    }

    private KrlArrayValue(KrlType type, double[] reals)
    {
        Type = type;
        _store = reals;
        _reals = true;
    }

    /// <summary>The array type.</summary>
    public KrlType Type { get; }

    /// <summary>True for a REAL array (its elements held as doubles).</summary>
    public bool HoldsReals => _reals;

    /// <summary>The number of elements.</summary>
    public int Length => _reals ? Reals.Length : Unsafe.As<object[]>(_store).Length;

    /// <summary>The elements of an array that is not a REAL array (INT, BOOL, CHAR, ENUM, structures), as the objects they are.</summary>
    public object[] Objects => _reals ? throw new InvalidOperationException("a REAL array holds doubles") : Unsafe.As<object[]>(_store);

    /// <summary>The elements of a REAL array.</summary>
    private double[] Reals => Unsafe.As<double[]>(_store);

    /// <summary>Element <paramref name="index"/> as an object (a REAL read this way is boxed: <see cref="Real"/> reads it without).</summary>
    public object this[int index]
    {
        get => _reals ? Reals[index] : Unsafe.As<object[]>(_store)[index];
        set
        {
            if (_reals)
            {
                Reals[index] = KrlValues.ToReal(value);
            }
            else
            {
                Unsafe.As<object[]>(_store)[index] = value;
            }
        }
    }

    /// <summary>The INT or REAL element <paramref name="index"/> as a REAL, without a box for a REAL array.</summary>
    public double Real(int index) => _reals ? Reals[index] : KrlValues.ToReal(Unsafe.As<object[]>(_store)[index]);

    /// <summary>Stores <paramref name="value"/> in element <paramref name="index"/> of a REAL array, without a box.</summary>
    public void SetReal(int index, double value)
    {
        if (_reals)
        {
            Reals[index] = value;
        }
        else
        {
            this[index] = value;
        }
    }

    /// <summary>The elements as objects, in a new array (a REAL array's boxed).</summary>
    public object[] ToObjects()
    {
        if (!_reals)
        {
            return (object[])Unsafe.As<object[]>(_store).Clone();
        }
        double[] reals = Reals;
        var items = new object[reals.Length];
        for (int i = 0; i < items.Length; i++)
        {
            items[i] = reals[i];
        }
        return items;
    }

    /// <summary>Copies the first <paramref name="count"/> elements of <paramref name="source"/> into this array as they are (no conversion).</summary>
    public void CopyFrom(KrlArrayValue source, int count)
    {
        if (_reals && source._reals)
        {
            source.Reals.AsSpan(0, count).CopyTo(Reals);
        }
        else if (!_reals && !source._reals)
        {
            Array.Copy(Unsafe.As<object[]>(source._store), Unsafe.As<object[]>(_store), count);
        }
        else
        {
            for (int i = 0; i < count; i++)
            {
                this[i] = source[i];
            }
        }
    }

    /// <summary>A deep copy.</summary>
    public KrlArrayValue Copy()
    {
        if (_reals)
        {
            return new KrlArrayValue(Type, (double[])Reals.Clone());
        }
        object[] objects = Unsafe.As<object[]>(_store);
        var items = new object[objects.Length];
        for (int i = 0; i < items.Length; i++)
        {
            items[i] = KrlValues.Copy(objects[i]);
        }
        return new KrlArrayValue(Type, items);
    }

    /// <summary>The initial value of a REAL array of <paramref name="type"/>: all 0.0.</summary>
    public static KrlArrayValue Zero(KrlType type) => new(type, new double[type.Length]);
}

namespace Machina.Simulation.Krl;

/// <summary>
/// Where a value is stored: a slot of a frame, cell or array, an element of a REAL array (<see cref="Reals"/>), a component of a structure (<see cref="Structure"/>), a row of a CHAR array (<c>text[i, ]</c>), or a signal of
/// an IO array (<see cref="Signals"/>). Assignments and OUT arguments write through it. A value type: finding the place of an
/// element or component and writing it allocates nothing (an OUT argument boxes it once).
/// </summary>
internal readonly struct KrlPlace(object[] container, int index, KrlType type, int sliceLength = 0)
{
    /// <summary>The array holding the slot (or the row); empty for a component of a structure (<see cref="Structure"/> holds it).</summary>
    public object[] Container { get; } = container;

    /// <summary>The slot (or the row's first element).</summary>
    public int Index { get; } = index;

    /// <summary>The type stored there.</summary>
    public KrlType Type { get; } = type;

    /// <summary>For a row of a CHAR array, its length (0 otherwise).</summary>
    public int SliceLength { get; } = sliceLength;

    /// <summary>The variable the place is part of, told after a write (e.g. <c>$OUT</c>), and the element's index in it.</summary>
    public (KrlCell Cell, int Element)? Root { get; init; }

    /// <summary>For a component of a structure, the structure: it holds the component (its <see cref="Index"/>) and notes that it was given a value.</summary>
    public KrlStructValue? Structure { get; init; }

    /// <summary>For an element (or a row) of a REAL array, the array: it holds the element (its <see cref="Index"/>) as a double; <see cref="Container"/> is empty.</summary>
    public KrlArrayValue? Reals { get; init; }

    /// <summary>For an IO array, its signals: the place is element <see cref="Index"/> of them, or all of them when it is -1.</summary>
    public KrlSignalArray? Signals { get; init; }

    /// <summary>The value stored (a copy of the row for a slice).</summary>
    public object Get() => Signals is { } signals
        ? Index < 0 ? signals.Get() : signals.Get(Index)
        : SliceLength > 0
        ? new KrlArrayValue(Type, Row())
        : Value;

    /// <summary>The value in the slot (not a row's, not a signal's).</summary>
    public object Value => Structure is { } structure ? structure[Index] : Reals is { } reals ? reals[Index] : Container[Index];

    /// <summary>A copy of the row's elements.</summary>
    private object[] Row()
    {
        if (Reals is not { } reals)
        {
            return Container[Index..(Index + SliceLength)];
        }
        var row = new object[SliceLength];
        for (int i = 0; i < row.Length; i++)
        {
            row[i] = reals[Index + i];
        }
        return row;
    }

    /// <summary>Stores the REAL <paramref name="value"/> (the place's type a REAL), without a box where the place holds numbers.</summary>
    public void SetReal(double value)
    {
        if (Type.Kind != KrlKind.Real || SliceLength > 0 || Signals is not null)
        {
            Set(value);
            return;
        }
        if (Structure is { } structure)
        {
            structure.SetReal(Index, value);
            structure.Give(Index);
        }
        else if (Reals is { } reals)
        {
            reals.SetReal(Index, value);
        }
        else
        {
            Container[Index] = value;
        }
        if (Root is { } root)
        {
            root.Cell.CountWrite();
            root.Cell.Written?.Invoke(root.Element);
        }
    }

    /// <summary>Replaces the value in the slot as it is (no conversion; not a row's, not a signal's).</summary>
    public void Replace(object value)
    {
        if (Structure is { } structure)
        {
            structure[Index] = value;
        }
        else if (Reals is { } reals)
        {
            reals[Index] = value;
        }
        else
        {
            Container[Index] = value;
        }
    }

    /// <summary>Stores <paramref name="value"/>, converted to the place's type.</summary>
    public void Set(object value)
    {
        if (Signals is { } signals)
        {
            if (Index < 0)
            {
                signals.Set(value);
            }
            else
            {
                signals.Set(Index, value);
            }
        }
        else if (SliceLength > 0)
        {
            if (value is string text && Reals is null)
            {
                KrlValues.SetText(Container, Index, SliceLength, text);
                Root?.Cell.CountWrite();
                Root?.Cell.Written?.Invoke(-1);
                return;
            }
            var source = (KrlArrayValue)value;
            for (int i = 0; i < SliceLength; i++)
            {
                object element = i < source.Length ? source[i] : Reals is null ? KrlValues.Box('\0') : 0.0;
                if (Reals is { } row)
                {
                    row[Index + i] = element;
                }
                else
                {
                    Container[Index + i] = element;
                }
            }
        }
        else if (Structure is { } structure)
        {
            if (Type.Kind == KrlKind.Real)
            {
                structure.SetReal(Index, KrlValues.ToReal(value));
            }
            else
            {
                structure[Index] = KrlConvert.To(Type, value, Type.Kind is KrlKind.Struct or KrlKind.Array ? structure[Index] : null);
            }
            structure.Give(Index);
        }
        else if (Reals is { } reals)
        {
            reals.SetReal(Index, KrlValues.ToReal(value));
        }
        else
        {
            Container[Index] = KrlConvert.To(Type, value, Container[Index]);
        }
        if (Root is { } root)
        {
            root.Cell.CountWrite();
            root.Cell.Written?.Invoke(root.Element);
        }
    }
}

namespace Machina.Simulation.Krl;

/// <summary>The kinds of KRL data types.</summary>
internal enum KrlKind
{
    /// <summary>A whole number (32 bits).</summary>
    Int,

    /// <summary>A floating-point number.</summary>
    Real,

    /// <summary>TRUE or FALSE.</summary>
    Bool,

    /// <summary>One character.</summary>
    Char,

    /// <summary>An enumeration value such as <c>#NOTIFY</c>.</summary>
    Enum,

    /// <summary>A structure (FRAME, E6POS, EKI_STATUS…).</summary>
    Struct,

    /// <summary>An array of 1 to 3 dimensions.</summary>
    Array,
}

/// <summary>A KRL data type: a simple type, a structure with its components, or an array of an element type.</summary>
internal sealed class KrlType
{
    private KrlType(KrlKind kind, string name)
    {
        Kind = kind;
        Name = name;
    }

    /// <summary>The kind.</summary>
    public KrlKind Kind { get; }

    /// <summary>The type's name as KRL writes it (INT, E6POS, CHAR[80]…).</summary>
    public string Name { get; }

    /// <summary>A structure's components, in order (empty otherwise).</summary>
    public IReadOnlyList<(string Name, KrlType Type)> Fields { get; private init; } = [];

    /// <summary>An array's element type (null otherwise).</summary>
    public KrlType? Element { get; private init; }

    /// <summary>An array's sizes (a 0 size: a parameter array whose size comes from the caller).</summary>
    public IReadOnlyList<int> Sizes => Dimensions;

    /// <summary>The same sizes as an array (the interpreter indexes them at every element access).</summary>
    public int[] Dimensions { get; private init; } = [];

    /// <summary>INT.</summary>
    public static KrlType Int { get; } = new(KrlKind.Int, "INT");

    /// <summary>REAL.</summary>
    public static KrlType Real { get; } = new(KrlKind.Real, "REAL");

    /// <summary>BOOL.</summary>
    public static KrlType Bool { get; } = new(KrlKind.Bool, "BOOL");

    /// <summary>CHAR.</summary>
    public static KrlType Char { get; } = new(KrlKind.Char, "CHAR");

    /// <summary>An enumeration (the twin does not tell one enumeration type from another).</summary>
    public static KrlType Enum { get; } = new(KrlKind.Enum, "ENUM");

    /// <summary>True for INT and REAL.</summary>
    public bool IsNumber => Kind is KrlKind.Int or KrlKind.Real;

    /// <summary>True for a CHAR array of one dimension (a string).</summary>
    public bool IsText => Kind == KrlKind.Array && Element!.Kind == KrlKind.Char && Sizes.Count == 1;

    /// <summary>A structure type.</summary>
    public static KrlType Struct(string name, params (string Name, KrlType Type)[] fields) => new(KrlKind.Struct, name) { Fields = fields };

    /// <summary>An array type of <paramref name="element"/> with <paramref name="sizes"/>.</summary>
    public static KrlType Array(KrlType element, params int[] sizes) =>
        new(KrlKind.Array, $"{element.Name}[{string.Join(",", sizes.Select(s => s == 0 ? "" : s.ToString(System.Globalization.CultureInfo.InvariantCulture)))}]")
        {
            Element = element, Dimensions = sizes,
        };

    /// <summary>The index of component <paramref name="field"/> (case-insensitive), or -1.</summary>
    public int FieldIndex(string field)
    {
        for (int i = 0; i < Fields.Count; i++)
        {
            if (string.Equals(Fields[i].Name, field, StringComparison.OrdinalIgnoreCase))
            {
                return i;
            }
        }
        return -1;
    }

    /// <summary>The map of the last other structure type converted into this one (see <see cref="FieldsFrom"/>).</summary>
    private sealed record FieldMap(KrlType Source, int[] Indexes);

    private FieldMap? _lastMap;

    /// <summary>
    /// For each component of structure type <paramref name="source"/>, the index of the component of this type with its name (-1
    /// for none), found once for the last source type (a motion converts its FRAME target into an E6POS at every statement).
    /// </summary>
    public int[] FieldsFrom(KrlType source)
    {
        if (_lastMap is { } map && ReferenceEquals(map.Source, source))
        {
            return map.Indexes;
        }
        var indexes = new int[source.Fields.Count];
        for (int i = 0; i < indexes.Length; i++)
        {
            indexes[i] = FieldIndex(source.Fields[i].Name);
        }
        _lastMap = new FieldMap(source, indexes);
        return indexes;
    }

    private int[]? _poseIndexes;

    private int[]? _axisIndexes;

    /// <summary>The indexes of the components A1 to A6 (-1 for one the type lacks), found once.</summary>
    public int[] AxisIndexes => _axisIndexes ??= [FieldIndex("A1"), FieldIndex("A2"), FieldIndex("A3"), FieldIndex("A4"), FieldIndex("A5"), FieldIndex("A6")];

    /// <summary>
    /// For a structure, its components' kinds when each is an INT, REAL, BOOL or CHAR (such a structure holds them unboxed, see
    /// <c>KrlStructValue</c>), or an empty array for a structure with other components; null until first found. Found from the
    /// type alone, so any controller may set it.
    /// </summary>
    internal KrlKind[]? NumberKinds { get; set; }

    /// <summary>The indexes of the components X, Y, Z, A, B and C (-1 for one the type lacks), found once.</summary>
    public int[] PoseIndexes => _poseIndexes ??= [FieldIndex("X"), FieldIndex("Y"), FieldIndex("Z"), FieldIndex("A"), FieldIndex("B"), FieldIndex("C")];

    /// <summary>The number of elements of an array type.</summary>
    public int Length => _length >= 0 ? _length : _length = Dimensions.Aggregate(1, (a, s) => a * Math.Max(s, 1));

    private int _length = -1;

    /// <inheritdoc/>
    public override string ToString() => Name;
}

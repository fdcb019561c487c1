namespace Machina.Simulation.Rapid;

/// <summary>What kind of value a RAPID type holds.</summary>
internal enum RapidTypeKind
{
    /// <summary><c>num</c> and its aliases (errnum, intnum…).</summary>
    Num,

    /// <summary><c>dnum</c> (the twin keeps it as a double, like num).</summary>
    Dnum,

    /// <summary><c>bool</c></summary>
    Bool,

    /// <summary><c>string</c> (at most 80 characters).</summary>
    String,

    /// <summary>A record of named components (pos, robtarget, a module's RECORD…).</summary>
    Record,

    /// <summary>Non-value data handled by instructions only (socketdev, signaldo, clock…).</summary>
    Opaque,
}

/// <summary>A RAPID data type: atomic, record or non-value; an alias (e.g. <c>errnum</c>) has the kind of the type it renames.</summary>
internal sealed class RapidType
{
    private readonly Dictionary<string, int> _index = new(StringComparer.OrdinalIgnoreCase);

    /// <summary>An atomic or non-value type.</summary>
    public RapidType(string name, RapidTypeKind kind, string? aliasOf = null, Func<object>? create = null)
    {
        Name = name;
        Kind = kind;
        Canonical = aliasOf ?? name;
        Create = create;
    }

    /// <summary>A record type with these components.</summary>
    public RapidType(string name, IReadOnlyList<(string Name, RapidDataType Type)> fields) : this(name, RapidTypeKind.Record)
    {
        Fields = fields;
        ScalarDefaults = new object?[fields.Count];
        Flat = true;
        for (int i = 0; i < fields.Count; i++)
        {
            _index[fields[i].Name] = i;
            Flat &= fields[i].Type is { Rank: 0, Element.Kind: not RapidTypeKind.Record };
            if (fields[i].Type is { Rank: 0, Element.Kind: RapidTypeKind.Num or RapidTypeKind.Dnum or RapidTypeKind.Bool or RapidTypeKind.String } scalar)
            {
                ScalarDefaults[i] = RapidValues.Default(scalar);
            }
        }
    }

    /// <summary>
    /// The initial values of a record type's num, dnum, bool and string components (shared: those values are never changed), null for
    /// a component that needs a value of its own (a record, an array or a non-value type); empty for other types.
    /// </summary>
    public object?[] ScalarDefaults { get; } = [];

    /// <summary>
    /// True for a record type none of whose components is a record or an array (pos, orient, a driver's request): a copy of its value
    /// shares every component (<see cref="RapidValues.Copy"/> shares numbers, strings and non-value data), so it copies the component
    /// references as they are, without looking at each.
    /// </summary>
    public bool Flat { get; }

    /// <summary>The type's name.</summary>
    public string Name { get; }

    /// <summary>What kind of value it holds.</summary>
    public RapidTypeKind Kind { get; }

    /// <summary>The name of the type that values are compatible with (the aliased type's name, or this name).</summary>
    public string Canonical { get; }

    /// <summary>The components of a record type (empty for others).</summary>
    public IReadOnlyList<(string Name, RapidDataType Type)> Fields { get; } = [];

    /// <summary>Makes a fresh value of a non-value type (null for others).</summary>
    public Func<object>? Create { get; }

    /// <summary>True for num, dnum and their aliases.</summary>
    public bool IsNumeric => Kind is RapidTypeKind.Num or RapidTypeKind.Dnum;

    /// <summary>The index of component <paramref name="name"/>, or -1.</summary>
    public int IndexOf(string name) => _index.TryGetValue(name, out int i) ? i : -1;

    /// <inheritdoc/>
    public override string ToString() => Name;
}

/// <summary>A static type: a RAPID type, or an array of it with <see cref="Rank"/> dimensions.</summary>
internal readonly record struct RapidDataType(RapidType Element, int Rank = 0)
{
    /// <summary>True when values of <paramref name="other"/> may be stored in data of this type.</summary>
    public bool Accepts(RapidDataType other) => Rank == other.Rank && (Element.Canonical.Equals(other.Element.Canonical, StringComparison.OrdinalIgnoreCase)
        || (Element.IsNumeric && other.Element.IsNumeric));

    /// <inheritdoc/>
    public override string ToString() => Rank == 0 ? Element.Name : $"{Element.Name}{{{string.Join(",", Enumerable.Repeat("*", Rank))}}}";
}

namespace Machina.Simulation.Krl;

/// <summary>
/// The program's own types: each <c>[GLOBAL] STRUC name type component[, …]</c> and <c>[GLOBAL] ENUM name value[, …]</c> of the
/// files loaded together, read before the files are parsed (a .src uses the types of a .dat read after it). A structure may use
/// another file's types; one whose component type exists nowhere refuses the load with its file and line. The twin does not
/// tell one enumeration type from another (an ENUM is the twin's ENUM), as for the system's enumerations.
/// </summary>
internal static class KrlUserTypes
{
    private sealed record Pending(string File, int Line, string Name, List<(string Type, string Component, int Size)> Components);

    /// <summary>The types declared in <paramref name="files"/> (name with extension, text), by name.</summary>
    public static IReadOnlyDictionary<string, KrlType> Collect(IEnumerable<(string Name, string Text)> files)
    {
        var types = new Dictionary<string, KrlType>(StringComparer.OrdinalIgnoreCase);
        var pending = new List<Pending>();
        foreach ((string file, string text) in files)
        {
            if (text.IndexOf("STRUC", StringComparison.OrdinalIgnoreCase) < 0 && text.IndexOf("ENUM", StringComparison.OrdinalIgnoreCase) < 0)
            {
                continue;
            }
            List<KrlToken> tokens = KrlLexer.Tokenize(file, text);
            for (int i = 0; i < tokens.Count; i++)
            {
                if (i > 0 && tokens[i - 1].Kind != KrlTokenKind.EndOfLine)
                {
                    continue;
                }
                int at = tokens[i].Is("GLOBAL") ? i + 1 : i;
                KrlToken keyword = tokens[Math.Min(at, tokens.Count - 1)];
                KrlToken name = tokens[Math.Min(at + 1, tokens.Count - 1)];
                if (!(keyword.Is("STRUC") || keyword.Is("ENUM")) || name.Kind != KrlTokenKind.Name)
                {
                    continue;
                }
                if (types.ContainsKey(name.Text) || pending.Exists(p => string.Equals(p.Name, name.Text, StringComparison.OrdinalIgnoreCase)))
                {
                    throw new KrlLoadException(file, name.Line, $"the type {name.Text} is declared twice");
                }
                if (keyword.Is("ENUM"))
                {
                    types[name.Text] = KrlType.Enum;
                }
                else
                {
                    pending.Add(new Pending(file, name.Line, name.Text, Components(file, tokens, at + 2)));
                }
            }
        }
        // A structure is made once the types of its components are known (another STRUC may come later in the files).
        while (pending.Count > 0)
        {
            Pending? ready = pending.Find(p => p.Components.TrueForAll(c => Find(types, c.Type) is not null));
            if (ready is null)
            {
                Pending stuck = pending[0];
                string missing = stuck.Components.First(c => Find(types, c.Type) is null).Type;
                throw new KrlLoadException(stuck.File, stuck.Line, $"unknown data type '{missing}' in STRUC {stuck.Name}");
            }
            pending.Remove(ready);
            types[ready.Name] = KrlType.Struct(ready.Name, [.. ready.Components.Select(c =>
            {
                KrlType type = Find(types, c.Type)!;
                return (c.Component, c.Size > 0 ? KrlType.Array(type, c.Size) : type);
            })]);
        }
        return types;
    }

    /// <summary>A predefined or declared type.</summary>
    public static KrlType? Find(IReadOnlyDictionary<string, KrlType>? types, string name) =>
        KrlTypes.Find(name) ?? (types is not null && types.TryGetValue(name, out KrlType? type) ? type : null);

    /// <summary>The components of a STRUC from <paramref name="at"/> to the end of its line: "type name[size]" groups, a group's names after commas.</summary>
    private static List<(string Type, string Component, int Size)> Components(string file, List<KrlToken> tokens, int at)
    {
        var components = new List<(string, string, int)>();
        string? type = null;
        int i = at;
        while (i < tokens.Count && tokens[i].Kind is not (KrlTokenKind.EndOfLine or KrlTokenKind.End))
        {
            if (tokens[i].Kind == KrlTokenKind.Name && i + 1 < tokens.Count && tokens[i + 1].Kind == KrlTokenKind.Name)
            {
                type = tokens[i].Text;
                i++;
            }
            if (type is null || tokens[i].Kind != KrlTokenKind.Name)
            {
                throw new KrlLoadException(file, tokens[i].Line, $"a STRUC component is written \"type name\", not {tokens[i].Display}");
            }
            string component = tokens[i].Text;
            i++;
            int size = 0;
            if (i + 2 < tokens.Count && tokens[i].IsSymbol("[") && tokens[i + 1].Kind == KrlTokenKind.Int && tokens[i + 2].IsSymbol("]"))
            {
                size = int.TryParse(tokens[i + 1].Text, System.Globalization.CultureInfo.InvariantCulture, out int n) && n is > 0 and <= 4096
                    ? n
                    : throw new KrlLoadException(file, tokens[i].Line, $"the array component {component} needs a size of 1 to 4096");
                i += 3;
            }
            components.Add((type, component, size));
            if (i < tokens.Count && tokens[i].IsSymbol(","))
            {
                i++;
            }
        }
        return components;
    }
}

using System.Text;
using System.Text.RegularExpressions;

namespace Machina.Tests.Conventions;

/// <summary>One line of a public API listing, parsed: a type, or a member of the type listed above it.</summary>
internal sealed record ApiEntry(string Line, string Owner, string Kind, string Name, bool IsStatic, string[] Parameters, bool[] Optional, string Type, bool Writable)
{
    /// <summary>True for a type line (class, struct, enum, delegate…).</summary>
    public bool IsType => Kind.StartsWith("type:", StringComparison.Ordinal);
}

/// <summary>How an original member fares against ours.</summary>
internal sealed record Verdict(ApiEntry Original, string Status, string OurOwner, IReadOnlyList<string> Candidates);

/// <summary>
/// Compares the original Machina.NET's public API listing with ours, member by member: "kept" when ported code using it still
/// compiles with the same meaning, "changed" when a member of that name exists but differs (or means something else), "removed"
/// when nothing of that name is left. The test is approximate where C# is lenient (it counts a call as compiling only when the
/// parameter and return types match exactly).
/// </summary>
internal static partial class OriginalApiComparison
{
    /// <summary>Original types whose name changed here.</summary>
    private static readonly Dictionary<string, string> RenamedTypes = new(StringComparer.Ordinal) { ["Action"] = "RobotAction" };

    /// <summary>Parses a listing into entries, each member attached to the type line above it.</summary>
    public static List<ApiEntry> Parse(IReadOnlyList<string> lines)
    {
        var entries = new List<ApiEntry>();
        string owner = "";
        bool isEnum = false;
        foreach (string line in lines)
        {
            Match t = TypeLine().Match(line);
            if (t.Success)
            {
                owner = t.Groups["name"].Value;
                string kind = t.Groups["kind"].Value;
                isEnum = kind == "enum";
                entries.Add(new ApiEntry(line, owner, "type:" + Normalize(kind), owner, false, [], [], "", false));
                continue;
            }
            entries.Add(ParseMember(line, owner, isEnum));
        }
        return entries;
    }

    private static string Normalize(string kind) => kind switch
    {
        "sealed class" or "abstract class" => "class",
        "readonly struct" => "struct",
        _ => kind,
    };

    private static ApiEntry ParseMember(string line, string owner, bool isEnum)
    {
        string text = line.StartsWith("[Obsolete] ", StringComparison.Ordinal) ? line["[Obsolete] ".Length..] : line;
        bool isStatic = false, isEvent = false;
        while (ModifierPrefix().Match(text) is { Success: true } m)
        {
            isStatic |= m.Groups[1].Value == "static";
            isEvent |= m.Groups[1].Value == "event";
            text = text[m.Length..];
        }
        if (!text.StartsWith(owner + ".", StringComparison.Ordinal))
        {
            throw new FormatException($"'{line}' does not belong to {owner}.");
        }
        string rest = text[(owner.Length + 1)..];
        if (isEvent)
        {
            string[] parts = rest.Split(" -> ");
            return new ApiEntry(line, owner, "event", parts[0], isStatic, [], [], parts[1], false);
        }
        if (isEnum)
        {
            string[] parts = rest.Split(" = ");
            return new ApiEntry(line, owner, "enum", parts[0], true, [], [], parts[1], false);
        }
        if (PropertyForm().Match(rest) is { Success: true } p)
        {
            string name = p.Groups["name"].Value;
            (string[] types, bool[] optional) = name.StartsWith("this[", StringComparison.Ordinal) ? SplitParameters(name[5..^1]) : ([], []);
            return new ApiEntry(line, owner, "property", name.StartsWith("this[", StringComparison.Ordinal) ? "this[]" : name, isStatic,
                types, optional, p.Groups["type"].Value, p.Groups["acc"].Value.Contains("set;", StringComparison.Ordinal));
        }
        if (FieldForm().Match(rest) is { Success: true } f)
        {
            // A field counts as a property; only an instance field that isn't readonly is writable (no one assigns a static one).
            string kind = f.Groups["kind"].Value;
            return new ApiEntry(line, owner, "property", f.Groups["name"].Value, isStatic || kind.StartsWith("static", StringComparison.Ordinal)
                || kind.StartsWith("const", StringComparison.Ordinal), [], [], f.Groups["type"].Value, kind == "field");
        }
        if (MethodForm().Match(rest) is { Success: true } mm)
        {
            (string[] types, bool[] optional) = SplitParameters(mm.Groups["params"].Value);
            string name = mm.Groups["name"].Value;
            bool ctor = !mm.Groups["ret"].Success;
            return new ApiEntry(line, owner, ctor ? "ctor" : "method", ctor ? ".ctor" : name, isStatic, types, optional, mm.Groups["ret"].Value, false);
        }
        throw new FormatException($"Cannot read '{line}'.");
    }

    /// <summary>Parameter types (with ref/out/in/params) without names, and which have defaults.</summary>
    private static (string[] Types, bool[] Optional) SplitParameters(string list)
    {
        var types = new List<string>();
        var optional = new List<bool>();
        foreach (string p in SplitTopLevel(list))
        {
            string decl = p;
            int eq = IndexOutsideQuotes(p, " = ");
            bool hasDefault = eq >= 0;
            if (hasDefault)
            {
                decl = p[..eq];
            }
            int space = decl.LastIndexOf(' ');
            types.Add(decl[..space].Replace("this ", "", StringComparison.Ordinal));
            optional.Add(hasDefault);
        }
        return (types.ToArray(), optional.ToArray());
    }

    private static int IndexOutsideQuotes(string s, string what)
    {
        bool quoted = false;
        for (int i = 0; i < s.Length; i++)
        {
            if ((s[i] == '"' || s[i] == '\'') && (i == 0 || s[i - 1] != '\\'))
            {
                quoted = !quoted;
            }
            if (!quoted && string.CompareOrdinal(s, i, what, 0, what.Length) == 0)
            {
                return i;
            }
        }
        return -1;
    }

    private static IEnumerable<string> SplitTopLevel(string list)
    {
        if (list.Length == 0)
        {
            yield break;
        }
        int depth = 0, start = 0;
        bool quoted = false;
        for (int i = 0; i < list.Length; i++)
        {
            char c = list[i];
            if ((c == '"' || c == '\'') && (i == 0 || list[i - 1] != '\\'))
            {
                quoted = !quoted;
            }
            else if (!quoted && (c == '<' || c == '['))
            {
                depth++;
            }
            else if (!quoted && (c == '>' || c == ']'))
            {
                depth--;
            }
            else if (!quoted && depth == 0 && c == ',' && i + 1 < list.Length && list[i + 1] == ' ')
            {
                yield return list[start..i];
                start = i + 2;
            }
        }
        yield return list[start..];
    }

    /// <summary>Maps each original type to ours of the same simple (nesting) name, or null when there is none.</summary>
    public static Dictionary<string, string?> MapTypes(IEnumerable<ApiEntry> original, IEnumerable<ApiEntry> ours)
    {
        var ourBySimple = SimpleNames(ours.Where(e => e.IsType).Select(e => e.Name));
        var byOurSimple = ourBySimple.ToDictionary(kv => kv.Value, kv => kv.Key, StringComparer.Ordinal);
        var map = new Dictionary<string, string?>(StringComparer.Ordinal);
        foreach ((string full, string simple) in SimpleNames(original.Where(e => e.IsType).Select(e => e.Name)))
        {
            string wanted = RenamedTypes.TryGetValue(simple, out string? renamed) ? renamed : simple;
            map[full] = byOurSimple.TryGetValue(wanted, out string? ourFull) ? ourFull : null;
        }
        return map;
    }

    private static Dictionary<string, string> SimpleNames(IEnumerable<string> typeNames)
    {
        var all = typeNames.ToHashSet(StringComparer.Ordinal);
        var result = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (string name in all)
        {
            result[name] = Simple(name, all);
        }
        return result;
    }

    private static string Simple(string name, HashSet<string> all)
    {
        int dot = name.LastIndexOf('.');
        if (dot < 0)
        {
            return name;
        }
        string parent = name[..dot];
        return all.Contains(parent) ? Simple(parent, all) + "." + name[(dot + 1)..] : name[(dot + 1)..];
    }

    /// <summary>The original's lines with its type names replaced by ours (types with no counterpart are left as they are).</summary>
    public static IReadOnlyList<string> Rewrite(IReadOnlyList<string> lines, Dictionary<string, string?> map)
    {
        var pairs = map.Where(kv => kv.Value is not null).OrderByDescending(kv => kv.Key.Length).ToArray();
        var pattern = new Regex(@"(?<![\w.])(" + string.Join("|", pairs.Select(kv => Regex.Escape(kv.Key))) + @")(?![\w])");
        var lookup = pairs.ToDictionary(kv => kv.Key, kv => kv.Value!, StringComparer.Ordinal);
        return lines.Select(l => pattern.Replace(l, m => lookup[m.Value])).ToArray();
    }

    /// <summary>Judges every original entry against ours.</summary>
    /// <param name="original">The original's listing.</param>
    /// <param name="ours">Our listing, without nullable annotations.</param>
    /// <param name="meaningChanged">Original lines that still compile here but mean something else (forced to "changed").</param>
    public static List<Verdict> Compare(IReadOnlyList<string> original, IReadOnlyList<string> ours, IReadOnlySet<string> meaningChanged)
    {
        var originalEntries = Parse(original);
        var ourEntries = Parse(ours);
        var map = MapTypes(originalEntries, ourEntries);
        var rewritten = Parse(Rewrite(original, map));
        var ourTypes = ourEntries.Where(e => e.IsType).ToDictionary(e => e.Name, StringComparer.Ordinal);
        var declared = ourEntries.Where(e => !e.IsType).ToLookup(e => e.Owner, StringComparer.Ordinal);
        var conversions = ImplicitConversions(ourEntries);
        // A member of a base class is a member too: walk each type's chain of listed base classes.
        IEnumerable<ApiEntry> MembersOf(string type)
        {
            for (string? t = type; t is not null; t = BaseClass(ourTypes.GetValueOrDefault(t), ourTypes))
            {
                foreach (ApiEntry e in declared[t])
                {
                    yield return e;
                }
            }
        }
        var verdicts = new List<Verdict>();
        for (int i = 0; i < originalEntries.Count; i++)
        {
            ApiEntry o = originalEntries[i], r = rewritten[i];
            string? ourOwner = map.GetValueOrDefault(o.Owner);
            if (ourOwner is null)
            {
                verdicts.Add(new Verdict(o, "removed", "", []));
                continue;
            }
            ApiEntry ourType = ourTypes[ourOwner];
            if (o.IsType)
            {
                bool sameType = r.Name == ourType.Name && r.Kind == ourType.Kind && (r.Kind != "type:delegate" || SameDelegate(r.Line, ourType.Line));
                verdicts.Add(new Verdict(o, sameType && !meaningChanged.Contains(o.Line) ? "kept" : "changed", ourOwner, [ourType.Line]));
                continue;
            }
            var sameName = MembersOf(ourOwner).Where(c => c.Name == r.Name && c.Kind == r.Kind).ToArray();
            bool compiles = sameName.Any(c => Compiles(r, c, conversions))
                || (r.Kind == "ctor" && r.Parameters.Length == 0 && ourType.Kind == "type:struct")
                || IsObjectMember(r)
                || (r.Name.StartsWith("implicit operator ", StringComparison.Ordinal) && conversions.Contains((r.Parameters[0], r.Type)));
            string status = compiles && !meaningChanged.Contains(o.Line) ? "kept" : sameName.Length > 0 || compiles ? "changed" : "removed";
            verdicts.Add(new Verdict(o, status, ourOwner, sameName.Select(c => c.Line).ToArray()));
        }
        return verdicts;
    }

    private static bool SameDelegate(string original, string ours) =>
        DelegateShape().Replace(original, "") == DelegateShape().Replace(ours, "");

    /// <summary>ToString(), Equals(object) and GetHashCode() exist on every type.</summary>
    private static bool IsObjectMember(ApiEntry e) => e.Kind == "method" && !e.IsStatic
        && ((e.Name is "ToString" or "GetHashCode" && e.Parameters.Length == 0) || (e.Name == "Equals" && e.Parameters is ["object"]));

    private static string? BaseClass(ApiEntry? type, Dictionary<string, ApiEntry> ourTypes)
    {
        if (type is null || type.Kind != "type:class")
        {
            return null;
        }
        int colon = type.Line.IndexOf(" : ", StringComparison.Ordinal);
        string? first = colon < 0 ? null : type.Line[(colon + 3)..].Split(", ")[0];
        return first is not null && ourTypes.ContainsKey(first) ? first : null;
    }

    /// <summary>Pairs (from, to) of our implicit conversions, plus the numeric widenings C# applies to arguments.</summary>
    private static HashSet<(string From, string To)> ImplicitConversions(IEnumerable<ApiEntry> ours)
    {
        var set = new HashSet<(string, string)> { ("int", "double"), ("int", "long"), ("float", "double"), ("long", "double"), ("int", "float") };
        foreach (ApiEntry e in ours.Where(e => e.Kind == "method" && e.Name.StartsWith("implicit operator ", StringComparison.Ordinal)))
        {
            set.Add((e.Parameters[0], e.Type));
        }
        return set;
    }

    private static bool Compiles(ApiEntry wanted, ApiEntry ours, HashSet<(string From, string To)> conversions)
    {
        switch (wanted.Kind)
        {
            case "method":
            case "ctor":
                if (wanted.IsStatic != ours.IsStatic || wanted.Type != ours.Type || ours.Parameters.Length < wanted.Parameters.Length)
                {
                    return false;
                }
                for (int i = 0; i < ours.Parameters.Length; i++)
                {
                    if (i >= wanted.Parameters.Length)
                    {
                        if (!ours.Optional[i])
                        {
                            return false;
                        }
                        continue;
                    }
                    bool converts = wanted.Parameters[i] == ours.Parameters[i] || conversions.Contains((wanted.Parameters[i], ours.Parameters[i]));
                    if (!converts || (wanted.Optional[i] && !ours.Optional[i]))
                    {
                        return false;
                    }
                }
                return true;
            case "property":
                return wanted.IsStatic == ours.IsStatic && wanted.Type == ours.Type && (!wanted.Writable || ours.Writable)
                    && wanted.Parameters.SequenceEqual(ours.Parameters);
            case "event":
                return wanted.Type == ours.Type;
            case "enum":
                return wanted.Type == ours.Type;
            default:
                return false;
        }
    }

    [GeneratedRegex(@"^(?:\[Obsolete\] )?(?<kind>delegate|enum|interface|readonly struct|struct|static class|abstract class|sealed class|class) (?<name>[^\s(]+)")]
    private static partial Regex TypeLine();

    [GeneratedRegex(@"^(static|override|virtual|abstract|event) ")]
    private static partial Regex ModifierPrefix();

    [GeneratedRegex(@"^(?<name>this\[.*\]|\w+) \{ (?<acc>[^}]*)\} -> (?<type>.+)$")]
    private static partial Regex PropertyForm();

    [GeneratedRegex(@"^(?<name>\w+) \((?<kind>(?:static )?(?:readonly )?field|const = .*)\) -> (?<type>.+)$")]
    private static partial Regex FieldForm();

    [GeneratedRegex(@"^(?<name>(?:implicit |explicit )?operator [^(]+|[\w<>, ]+?)\((?<params>.*)\)(?: -> (?<ret>.+))?$")]
    private static partial Regex MethodForm();

    [GeneratedRegex(@" \w+(?=[,)])")]
    private static partial Regex DelegateShape();

    /// <summary>The generated part of docs/migrating.md: a summary and one table per original type.</summary>
    public static string Table(IReadOnlyList<Verdict> verdicts, IReadOnlyDictionary<string, string> replacements)
    {
        var sb = new StringBuilder();
        int members = verdicts.Count(v => !v.Original.IsType);
        int kept = verdicts.Count(v => !v.Original.IsType && v.Status == "kept");
        sb.Append(Invariant($"Of the original's {members} public members, {kept} compile unchanged with the same meaning here, "))
          .Append(Invariant($"{verdicts.Count(v => !v.Original.IsType && v.Status == "changed")} changed and "))
          .Append(Invariant($"{verdicts.Count(v => !v.Original.IsType && v.Status == "removed")} were removed (counting a type that is gone as all its members).\n\n"));
        sb.Append("| Original type | Members | Kept | Changed | Removed |\n|---|---|---|---|---|\n");
        foreach (var group in verdicts.Where(v => !v.Original.IsType).GroupBy(v => v.Original.Owner))
        {
            sb.Append(Invariant($"| `{group.Key}` | {group.Count()} | {group.Count(v => v.Status == "kept")} | {group.Count(v => v.Status == "changed")} | {group.Count(v => v.Status == "removed")} |\n"));
        }
        foreach (var group in verdicts.GroupBy(v => v.Original.Owner))
        {
            Verdict typeVerdict = group.First();
            sb.Append("\n### `").Append(group.Key).Append('`');
            sb.Append(typeVerdict.OurOwner.Length > 0 ? $" → `{typeVerdict.OurOwner}`\n\n" : " (gone)\n\n");
            sb.Append("| Original member | Status | Replacement |\n|---|---|---|\n");
            bool typeGone = typeVerdict.OurOwner.Length == 0;
            foreach (Verdict v in typeGone ? new[] { typeVerdict } : group.ToArray())
            {
                string text = v.Status == "kept" ? "" : replacements.GetValueOrDefault(v.Original.Line) ?? Suggest(v);
                sb.Append("| `").Append(v.Original.Line).Append("` | ").Append(v.Status).Append(" | ").Append(text).Append(" |\n");
            }
        }
        return sb.ToString();
    }

    private static string Suggest(Verdict v) => v.Candidates.Count > 0 && !v.Original.IsType
        ? "now " + string.Join("; ", v.Candidates.Select(c => "`" + c + "`"))
        : "TODO";

    private static string Invariant(FormattableString s) => FormattableString.Invariant(s);

    /// <summary>The Replacement column of each row already in the document, by original member line.</summary>
    public static Dictionary<string, string> ReadReplacements(string markdown)
    {
        var result = new Dictionary<string, string>(StringComparer.Ordinal);
        foreach (Match m in Row().Matches(markdown))
        {
            result[m.Groups["line"].Value] = m.Groups["text"].Value.Trim();
        }
        return result;
    }

    [GeneratedRegex(@"^\| `(?<line>.+?)` \| (?<status>kept|changed|removed) \| (?<text>.*) \|$", RegexOptions.Multiline)]
    private static partial Regex Row();
}

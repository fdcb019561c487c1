using System.Globalization;
using System.Reflection;
using System.Text;

namespace Machina.Tests.Docs;

/// <summary>
/// Writes the parts of docs/reference.md that come from the code: the C# signatures of <see cref="Robot"/>'s members (by
/// reflection) and, for each action verb, the native lines its example produces on every brand, offline (the real compilers)
/// and online (the brand's issue-time refusals and the real wire encoders of its driver).
/// </summary>
internal static class ReferenceGenerator
{
    private static readonly (RobotType Brand, string Label)[] Brands =
    [
        (RobotType.ABB, "ABB"), (RobotType.UR, "UR"), (RobotType.KUKA, "KUKA"), (RobotType.ZMORPH, "ZMorph"), (RobotType.MARLIN, "Marlin"),
    ];

    /// <summary>Most lines shown in one cell.</summary>
    private const int MaxLinesShown = 8;

    /// <summary>Every public member of <see cref="Robot"/> (methods, properties, events) by name, as the reference must cover them.</summary>
    internal static SortedSet<string> PublicMemberNames()
    {
        var names = new SortedSet<string>(StringComparer.Ordinal);
        foreach (MemberInfo member in typeof(Robot).GetMembers(BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly))
        {
            if (member is MethodInfo { IsSpecialName: true } or ConstructorInfo)
            {
                continue;
            }
            names.Add(member.Name);
        }
        return names;
    }

    /// <summary>The action verbs: public methods of <see cref="Robot"/> that are also instructions of the text language.</summary>
    internal static SortedSet<string> ActionVerbs() =>
        new(PublicMemberNames().Where(n => InstructionCatalog.Find(n) is not null), StringComparer.Ordinal);

    /// <summary>The lines of the signatures region of a section documenting <paramref name="names"/>.</summary>
    internal static List<string> Signatures(IEnumerable<string> names)
    {
        var lines = new List<string> { "```csharp" };
        foreach (string name in names)
        {
            var members = typeof(Robot).GetMember(name, BindingFlags.Public | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly);
            lines.AddRange(members.Select(Signature).Order(StringComparer.Ordinal).OrderBy(s => s.Length));
        }
        lines.Add("```");
        return lines;
    }

    private static readonly NullabilityInfoContext Nullability = new();

    private static string Signature(MemberInfo member)
    {
        string obsolete = member.GetCustomAttribute<ObsoleteAttribute>() is not null ? "[Obsolete] " : "";
        switch (member)
        {
            case MethodInfo m:
                string parameters = string.Join(", ", m.GetParameters().Select(Parameter));
                return $"{obsolete}{(m.IsStatic ? "static " : "")}{TypeName(m.ReturnType, Nullability.Create(m.ReturnParameter))} {m.Name}({parameters})";
            case PropertyInfo p:
                bool isStatic = p.GetMethod?.IsStatic ?? false;
                string accessors = p.SetMethod is { IsPublic: true } ? "{ get; set; }" : "{ get; }";
                return $"{obsolete}{(isStatic ? "static " : "")}{TypeName(p.PropertyType, Nullability.Create(p))} {p.Name} {accessors}";
            case EventInfo e:
                return $"{obsolete}event {TypeName(e.EventHandlerType!, Nullability.Create(e))} {e.Name}";
            case Type { BaseType: var b } d when b == typeof(MulticastDelegate):
                MethodInfo invoke = d.GetMethod("Invoke")!;
                string arguments = string.Join(", ", invoke.GetParameters().Select(Parameter));
                return $"{obsolete}delegate {TypeName(invoke.ReturnType, Nullability.Create(invoke.ReturnParameter))} {d.Name}({arguments})";
            default:
                throw new InvalidOperationException($"Unexpected member {member}.");
        }
    }

    private static string Parameter(ParameterInfo p)
    {
        string text = $"{TypeName(p.ParameterType, Nullability.Create(p))} {p.Name}";
        if (p.HasDefaultValue)
        {
            text += " = " + p.DefaultValue switch
            {
                null when p.ParameterType.IsValueType && Nullable.GetUnderlyingType(p.ParameterType) is null => "default",
                null => "null",
                bool b => b ? "true" : "false",
                string s => $"\"{s}\"",
                Enum e => $"{e.GetType().Name}.{e}",
                IFormattable f => f.ToString(null, CultureInfo.InvariantCulture),
                object o => o.ToString(),
            };
        }
        return text;
    }

    private static string TypeName(Type type, NullabilityInfo? nullability)
    {
        if (Nullable.GetUnderlyingType(type) is Type inner)
        {
            return TypeName(inner, null) + "?";
        }
        string name = type switch
        {
            _ when type == typeof(void) => "void",
            _ when type == typeof(bool) => "bool",
            _ when type == typeof(int) => "int",
            _ when type == typeof(long) => "long",
            _ when type == typeof(double) => "double",
            _ when type == typeof(string) => "string",
            _ when type == typeof(object) => "object",
            _ when type.IsGenericType => $"{type.Name[..type.Name.IndexOf('`', StringComparison.Ordinal)]}<" +
                string.Join(", ", type.GetGenericArguments().Select((a, i) => TypeName(a, nullability?.GenericTypeArguments.ElementAtOrDefault(i)))) + ">",
            _ => type.Name,
        };
        bool nullable = !type.IsValueType && nullability is { ReadState: NullabilityState.Nullable } or { ReadState: NullabilityState.Unknown, WriteState: NullabilityState.Nullable };
        return nullable ? name + "?" : name;
    }

    /// <summary>The lines of the native region of an action verb's section: a table of what its example does on every brand.</summary>
    internal static List<string> NativeTable(Action<Robot> example)
    {
        var lines = new List<string>
        {
            "| Brand | Offline: lines added to the program | Online: refused, or sent to Machina's driver |",
            "|---|---|---|",
        };
        foreach ((RobotType brand, string label) in Brands)
        {
            string online = OnlineBrands.TryFor(brand) is IOnlineBrand onlineBrand ? Cell(Online(onlineBrand, example)) : "no online control";
            lines.Add($"| {label} | {Cell(Offline(brand, example))} | {online} |");
        }
        return lines;
    }

    /// <summary>The program lines (trimmed) that the example adds to the preamble's program, or the refusal.</summary>
    private static List<string> Offline(RobotType brand, Action<Robot> example)
    {
        Robot before = Robot.Create("Example", brand);
        ReferenceExamples.Preamble(before);
        Robot after = Robot.Create("Example", brand);
        ReferenceExamples.Preamble(after);
        try
        {
            example(after);
        }
        catch (Exception ex) when (ex is ActionRefusedException or ArgumentException)
        {
            return [$"refused with {ex.GetType().Name}: {ex.Message}"];
        }
        var options = new CompileOptions { HumanComments = false };
        string[] old = [.. before.Compile(brand, options).Files.SelectMany(f => f.Lines).Select(l => l.Trim())];
        string[] now = [.. after.Compile(brand, options).Files.SelectMany(f => f.Lines).Select(l => l.Trim())];
        List<string> added = [.. Added(old, now).Where(l => l.Length > 0)];
        if (added.Count > MaxLinesShown)
        {
            // A long run (a printer's arc as straight segments): the first lines, how many are left out, and the last.
            added = [.. added.Take(MaxLinesShown - 2), $"(… {added.Count - MaxLinesShown + 1} more lines …)", added[^1]];
        }
        return added.Count > 0 ? added : ["(no line)"];
    }

    /// <summary>
    /// The lines of <paramref name="now"/> that are not in a longest common subsequence with <paramref name="old"/>, in order:
    /// a line equal to one of the program's own (a loop's <c>end</c>) counts where it stands, not where it first fits.
    /// </summary>
    internal static IEnumerable<string> Added(string[] old, string[] now)
    {
        // kept[i, j]: the longest common subsequence of old[i..] and now[j..].
        var kept = new int[old.Length + 1, now.Length + 1];
        for (int i = old.Length - 1; i >= 0; i--)
        {
            for (int j = now.Length - 1; j >= 0; j--)
            {
                kept[i, j] = string.Equals(old[i], now[j], StringComparison.Ordinal) ? kept[i + 1, j + 1] + 1 : Math.Max(kept[i + 1, j], kept[i, j + 1]);
            }
        }
        // Each old line is matched as late as it can be: the example's lines come before the program's closing ones.
        int a = 0, b = 0;
        while (b < now.Length)
        {
            if (kept[a, b + 1] == kept[a, b])
            {
                yield return now[b++];
            }
            else if (string.Equals(old[a], now[b], StringComparison.Ordinal))
            {
                a++;
                b++;
            }
            else
            {
                a++;
            }
        }
    }

    /// <summary>The wire text each example action is sent as, replayed on a cursor as the release cursor sees it, or the refusal.</summary>
    private static List<string> Online(IOnlineBrand brand, Action<Robot> example)
    {
        Robot robot = Robot.Create("Example", brand.Brand);
        ReferenceExamples.Preamble(robot);
        int preamble = robot.GetProgramActions().Count;
        example(robot);
        var cursor = new RobotCursor();
        var wire = new List<string>();
        IReadOnlyList<RobotAction> actions = robot.GetProgramActions();
        for (int i = 0; i < actions.Count; i++)
        {
            RobotAction action = actions[i];
            if (i >= preamble && brand.WhyCannotStream(action) is string refusal)
            {
                wire.Add($"refused with ActionRefusedException: {new ActionRefusedException(action, refusal).Message}");
                return wire;
            }
            Assert.Null(cursor.TryApply(action));
            if (i >= preamble)
            {
                wire.AddRange(Encode(brand.Brand, action, cursor));
            }
        }
        return wire.Count > 0 ? wire : ["(nothing sent)"];
    }

    private static IEnumerable<string> Encode(RobotType brand, RobotAction action, RobotCursor after)
    {
        switch (brand)
        {
            case RobotType.ABB:
                var requests = new List<AbbRequest>();
                AbbActionEncoder.Encode(action, after, requests);
                return requests.Select(r => r.ToWireText());
            case RobotType.UR:
                var values = new int[UrActionEncoder.MaxValues];
                int n = UrActionEncoder.Encode(action, after, values);
                return n == 0 ? [] : [string.Join(" ", values[..n].Select(v => v.ToString(CultureInfo.InvariantCulture)))];
            case RobotType.KUKA:
                if (KukaActionEncoder.Encode(action, action.Id, after) is not KukaInstruction instruction)
                {
                    return [];
                }
                var sb = new StringBuilder();
                instruction.AppendTo(sb);
                return [sb.ToString()];
            default:
                throw new ArgumentOutOfRangeException(nameof(brand), brand, "No online encoder.");
        }
    }

    /// <summary>Lines as one table cell: each in a code span, separated by line breaks.</summary>
    private static string Cell(IEnumerable<string> lines) => string.Join("<br>", lines.Select(l =>
        l.StartsWith("refused with ", StringComparison.Ordinal) || l.StartsWith('(')
            ? l.Replace("|", "\\|", StringComparison.Ordinal)
            : (l.Contains('`', StringComparison.Ordinal) ? $"`` {l} ``" : $"`{l}`").Replace("|", "\\|", StringComparison.Ordinal)));
}

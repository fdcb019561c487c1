using System.Globalization;
using System.Reflection;
using System.Runtime.CompilerServices;
using System.Text;

namespace Machina.Tests.Conventions;

/// <summary>
/// The public surface of an assembly as stable sorted text, one line per type or member: what a user can see and call.
/// Used for the checked-in PublicAPI.txt listings and for the listing of the original Machina.NET.
/// </summary>
/// <remarks>
/// Line forms (each member line starts with its type's full name, so a line can be compared on its own):
/// <code>
/// struct Machina.Vector : System.IEquatable&lt;Machina.Vector&gt;
/// Machina.Vector.Vector(double X, double Y, double Z)
/// Machina.Vector.X { get; init; } -> double
/// Machina.Vector.DistanceTo(Machina.Vector other) -> double
/// static Machina.Vector.operator +(Machina.Vector a, Machina.Vector b) -> Machina.Vector
/// Machina.Robot.Version (static readonly field) -> string
/// event Machina.Robot.ActionIssued -> Machina.Robot.ActionIssuedHandler?
/// </code>
/// Reference types carry their nullable annotation (<c>?</c>) when the assembly has them.
/// </remarks>
internal sealed class PublicApiListing
{
    private readonly bool _annotations;

    private PublicApiListing(bool annotations) => _annotations = annotations;

    private const BindingFlags Declared =
        BindingFlags.Public | BindingFlags.NonPublic | BindingFlags.Instance | BindingFlags.Static | BindingFlags.DeclaredOnly;

    /// <summary>
    /// The listing of every public type of <paramref name="assembly"/>, types in ordinal order, each followed by its members.
    /// Without <paramref name="annotations"/> reference types carry no nullable <c>?</c> (to compare with unannotated code).
    /// </summary>
    public static IReadOnlyList<string> Describe(Assembly assembly, bool annotations = true) => new PublicApiListing(annotations).DescribeAll(assembly);

    private IReadOnlyList<string> DescribeAll(Assembly assembly)
    {
        var lines = new List<string>();
        foreach (Type type in assembly.GetExportedTypes().OrderBy(t => Name(t), StringComparer.Ordinal))
        {
            lines.Add(TypeLine(type));
            if (IsDelegate(type))
            {
                continue;
            }
            lines.AddRange(Members(type).Distinct().OrderBy(l => l, StringComparer.Ordinal));
        }
        return lines;
    }

    /// <summary>The listing as file text (LF line ends, final newline).</summary>
    public static string ToText(IEnumerable<string> lines) => string.Concat(lines.Select(l => l + "\n"));

    /// <summary>Lines of a listing file, ignoring blank lines and <c>#</c> comments.</summary>
    public static IReadOnlyList<string> Parse(string text) =>
        text.Split('\n').Select(l => l.TrimEnd('\r')).Where(l => l.Length > 0 && !l.StartsWith('#')).ToArray();

    private static bool IsDelegate(Type t) => typeof(Delegate).IsAssignableFrom(t.BaseType) || t.BaseType?.FullName == "System.MulticastDelegate";

    private string TypeLine(Type t)
    {
        if (IsDelegate(t))
        {
            MethodInfo invoke = t.GetMethod("Invoke")!;
            return $"delegate {Name(t)}({Parameters(invoke.GetParameters())}) -> {ReturnName(invoke)}";
        }
        string kind = t.IsEnum ? "enum" : t.IsInterface ? "interface" : t.IsValueType ? (IsReadOnly(t) ? "readonly struct" : "struct")
            : t.IsAbstract && t.IsSealed ? "static class" : t.IsAbstract ? "abstract class" : t.IsSealed ? "sealed class" : "class";
        var bases = new List<string>();
        if (t.IsEnum)
        {
            bases.Add(Name(Enum.GetUnderlyingType(t)));
        }
        else if (t.IsClass && t.BaseType is { } b && b.FullName != "System.Object")
        {
            bases.Add(Name(b));
        }
        if (!t.IsEnum)
        {
            bases.AddRange(t.GetInterfaces().Where(i => i.IsPublic || i.IsNestedPublic).Select(i => Name(i)).OrderBy(n => n, StringComparer.Ordinal));
        }
        return $"{Obsolete(t)}{kind} {Name(t)}{(bases.Count > 0 ? " : " + string.Join(", ", bases) : "")}";
    }

    private IEnumerable<string> Members(Type t)
    {
        string owner = Name(t);
        if (t.IsEnum)
        {
            foreach (FieldInfo f in t.GetFields(BindingFlags.Public | BindingFlags.Static))
            {
                yield return $"{Obsolete(f)}{owner}.{f.Name} = {Convert.ToString(f.GetRawConstantValue(), CultureInfo.InvariantCulture)}";
            }
            yield break;
        }
        foreach (MemberInfo m in t.GetMembers(Declared).Where(Visible))
        {
            string? line = m switch
            {
                ConstructorInfo c when !c.IsStatic => $"{owner}.{t.Name.Split('`')[0]}({Parameters(c.GetParameters())})",
                MethodInfo mi when !mi.IsSpecialName || mi.Name.StartsWith("op_", StringComparison.Ordinal) => Method(owner, mi),
                PropertyInfo p => Property(owner, p),
                FieldInfo f when !f.IsSpecialName => Field(owner, f),
                EventInfo e => $"event {owner}.{e.Name} -> {Name(e.EventHandlerType!, Nullability(e))}",
                _ => null,
            };
            if (line is not null && !IsCompilerGenerated(m))
            {
                yield return Obsolete(m) + line;
            }
        }
    }

    private static bool Visible(MemberInfo m) => m switch
    {
        MethodBase mb => mb.IsPublic || mb.IsFamily || mb.IsFamilyOrAssembly,
        FieldInfo f => f.IsPublic || f.IsFamily || f.IsFamilyOrAssembly,
        PropertyInfo p => p.GetAccessors(true).Any(a => a.IsPublic || a.IsFamily || a.IsFamilyOrAssembly),
        EventInfo e => e.AddMethod is { } a && (a.IsPublic || a.IsFamily || a.IsFamilyOrAssembly),
        _ => false,
    };

    // Records' compiler-made members that no user calls by name (EqualityContract, PrintMembers, <Clone>$).
    private static bool IsCompilerGenerated(MemberInfo m) =>
        m.Name.Contains('<') || m.Name is "EqualityContract" or "PrintMembers";

    private string Method(string owner, MethodInfo m)
    {
        string name = OperatorNames.TryGetValue(m.Name, out string? op) ? op : m.Name;
        if (m.Name is "op_Implicit" or "op_Explicit")
        {
            name += " " + ReturnName(m);
        }
        if (m.IsGenericMethodDefinition)
        {
            name += "<" + string.Join(", ", m.GetGenericArguments().Select(a => a.Name)) + ">";
        }
        string extension = m.IsDefined(typeof(ExtensionAttribute), false) ? "this " : "";
        return $"{Modifiers(m)}{owner}.{name}({extension}{Parameters(m.GetParameters())}) -> {ReturnName(m)}";
    }

    private static string Modifiers(MethodInfo m)
    {
        if (m.IsStatic)
        {
            return "static ";
        }
        if (m.DeclaringType!.IsInterface)
        {
            return "";
        }
        if (m.IsAbstract)
        {
            return "abstract ";
        }
        if (m.IsVirtual && !m.IsFinal)
        {
            return m.GetBaseDefinition() != m ? "override " : "virtual ";
        }
        return m.IsVirtual && m.GetBaseDefinition() != m ? "override " : "";
    }

    private string Property(string owner, PropertyInfo p)
    {
        MethodInfo accessor = p.GetAccessors(true).First();
        ParameterInfo[] index = p.GetIndexParameters();
        string name = index.Length > 0 ? $"this[{Parameters(index)}]" : p.Name;
        var accessors = new List<string>();
        if (p.GetMethod is { } g && (g.IsPublic || g.IsFamily || g.IsFamilyOrAssembly))
        {
            accessors.Add("get;");
        }
        if (p.SetMethod is { } s && (s.IsPublic || s.IsFamily || s.IsFamilyOrAssembly))
        {
            bool init = s.ReturnParameter.GetRequiredCustomModifiers().Any(x => x.FullName == "System.Runtime.CompilerServices.IsExternalInit");
            accessors.Add(init ? "init;" : "set;");
        }
        return $"{Modifiers(accessor)}{owner}.{name} {{ {string.Join(" ", accessors)} }} -> {Name(p.PropertyType, Nullability(p))}";
    }

    private string Field(string owner, FieldInfo f)
    {
        string kind = f.IsLiteral ? $"const = {Literal(f.GetRawConstantValue())}" : (f.IsStatic ? "static " : "") + (f.IsInitOnly ? "readonly field" : "field");
        return $"{owner}.{f.Name} ({kind}) -> {Name(f.FieldType, Nullability(f))}";
    }

    private string Parameters(ParameterInfo[] ps) => string.Join(", ", ps.Select(Parameter));

    private string Parameter(ParameterInfo p)
    {
        var sb = new StringBuilder();
        Type type = p.ParameterType;
        if (type.IsByRef)
        {
            sb.Append(p.IsOut ? "out " : p.IsIn ? "in " : "ref ");
            type = type.GetElementType()!;
        }
        if (p.IsDefined(typeof(ParamArrayAttribute), false))
        {
            sb.Append("params ");
        }
        sb.Append(Name(type, Nullability(p))).Append(' ').Append(p.Name);
        if (p.HasDefaultValue)
        {
            bool structDefault = p.RawDefaultValue is null && type.IsValueType && Nullable.GetUnderlyingType(type) is null;
            sb.Append(" = ").Append(structDefault ? "default" : Literal(p.RawDefaultValue));
        }
        return sb.ToString();
    }

    private static string Literal(object? value) => value switch
    {
        null => "null",
        string s => "\"" + s.Replace("\\", "\\\\", StringComparison.Ordinal).Replace("\"", "\\\"", StringComparison.Ordinal)
            .Replace("\n", "\\n", StringComparison.Ordinal).Replace("\r", "\\r", StringComparison.Ordinal).Replace("\t", "\\t", StringComparison.Ordinal) + "\"",
        char c => "'" + (c switch { '\n' => "\\n", '\r' => "\\r", '\t' => "\\t", '\'' => "\\'", '\\' => "\\\\", _ => c.ToString() }) + "'",
        bool b => b ? "true" : "false",
        double d => d.ToString("R", CultureInfo.InvariantCulture),
        float f => f.ToString("R", CultureInfo.InvariantCulture),
        IFormattable x => x.ToString(null, CultureInfo.InvariantCulture),
        _ => value.ToString() ?? "",
    };

    private string ReturnName(MethodInfo m) => Name(m.ReturnType, Nullability(m.ReturnParameter));

    private static string Obsolete(MemberInfo m) =>
        m.CustomAttributes.Any(a => a.AttributeType.FullName == "System.ObsoleteAttribute") ? "[Obsolete] " : "";

    private static bool IsReadOnly(Type t) =>
        t.CustomAttributes.Any(a => a.AttributeType.FullName == "System.Runtime.CompilerServices.IsReadOnlyAttribute");

    private NullabilityInfo? Nullability(ParameterInfo p) => Safe(() => new NullabilityInfoContext().Create(p));

    private NullabilityInfo? Nullability(PropertyInfo p) => Safe(() => new NullabilityInfoContext().Create(p));

    private NullabilityInfo? Nullability(FieldInfo f) => Safe(() => new NullabilityInfoContext().Create(f));

    private NullabilityInfo? Nullability(EventInfo e) => Safe(() => new NullabilityInfoContext().Create(e));

    private NullabilityInfo? Safe(Func<NullabilityInfo> create)
    {
        if (!_annotations)
        {
            return null;
        }
        try
        {
            return create();
        }
        catch (Exception ex) when (ex is InvalidOperationException or FileNotFoundException or NotSupportedException)
        {
            return null;
        }
    }

    /// <summary>C# name of a type: keywords for the built-in types, full names with '.' for nested types, generic arguments spelled out.</summary>
    private string Name(Type t, NullabilityInfo? n = null)
    {
        if (t.IsGenericParameter)
        {
            return t.Name + (n?.ReadState == NullabilityState.Nullable && !t.IsValueType ? "?" : "");
        }
        if (t.IsArray)
        {
            string element = Name(t.GetElementType()!, n?.ElementType);
            return element + "[" + new string(',', t.GetArrayRank() - 1) + "]" + Suffix(t, n);
        }
        if (t.IsGenericType && t.GetGenericTypeDefinition().FullName == "System.Nullable`1")
        {
            return Name(t.GetGenericArguments()[0]) + "?";
        }
        if (Keywords.TryGetValue(t.FullName ?? "", out string? keyword))
        {
            return keyword + Suffix(t, n);
        }
        string name = (t.IsNested ? Name(t.DeclaringType!) + "." : t.Namespace is { Length: > 0 } ns ? ns + "." : "") + t.Name.Split('`')[0];
        if (t.IsGenericType)
        {
            Type[] args = t.GetGenericArguments();
            int skip = t.IsNested ? t.DeclaringType!.GetGenericArguments().Length : 0;
            var argNames = args.Skip(skip).Select((a, i) => Name(a, n is { } ni && ni.GenericTypeArguments.Length == args.Length ? ni.GenericTypeArguments[i + skip] : null));
            name += "<" + string.Join(", ", argNames) + ">";
        }
        return name + Suffix(t, n);
    }

    private string Suffix(Type t, NullabilityInfo? n) => !t.IsValueType && n?.ReadState == NullabilityState.Nullable ? "?" : "";

    private static readonly Dictionary<string, string> Keywords = new()
    {
        ["System.Void"] = "void", ["System.Object"] = "object", ["System.String"] = "string", ["System.Boolean"] = "bool",
        ["System.Byte"] = "byte", ["System.SByte"] = "sbyte", ["System.Char"] = "char", ["System.Int16"] = "short",
        ["System.UInt16"] = "ushort", ["System.Int32"] = "int", ["System.UInt32"] = "uint", ["System.Int64"] = "long",
        ["System.UInt64"] = "ulong", ["System.Single"] = "float", ["System.Double"] = "double", ["System.Decimal"] = "decimal",
    };

    private static readonly Dictionary<string, string> OperatorNames = new()
    {
        ["op_Addition"] = "operator +", ["op_Subtraction"] = "operator -", ["op_Multiply"] = "operator *",
        ["op_Division"] = "operator /", ["op_Modulus"] = "operator %", ["op_UnaryNegation"] = "operator -",
        ["op_UnaryPlus"] = "operator +", ["op_Equality"] = "operator ==", ["op_Inequality"] = "operator !=",
        ["op_LessThan"] = "operator <", ["op_GreaterThan"] = "operator >", ["op_LessThanOrEqual"] = "operator <=",
        ["op_GreaterThanOrEqual"] = "operator >=", ["op_Implicit"] = "implicit operator", ["op_Explicit"] = "explicit operator",
        ["op_LogicalNot"] = "operator !", ["op_BitwiseAnd"] = "operator &", ["op_BitwiseOr"] = "operator |",
        ["op_ExclusiveOr"] = "operator ^", ["op_OnesComplement"] = "operator ~", ["op_True"] = "operator true",
        ["op_False"] = "operator false", ["op_Increment"] = "operator ++", ["op_Decrement"] = "operator --",
    };
}

using System.Collections;
using System.Reflection;

namespace Machina.Tests.Support;

/// <summary>Every field of a cursor, read by reflection, to check that an action refused or undone left it exactly as it was.</summary>
internal static class CursorFields
{
    /// <summary>
    /// Every instance field of <paramref name="cursor"/> by name; collections as lists of their entries. Left out: the sinks it
    /// reports through (delegates, set once) and the counter of its own solves (work done, not state).
    /// </summary>
    internal static Dictionary<string, object?> Of(RobotCursor cursor)
    {
        var fields = new Dictionary<string, object?>(StringComparer.Ordinal);
        foreach (FieldInfo field in typeof(RobotCursor).GetFields(BindingFlags.Instance | BindingFlags.Public | BindingFlags.NonPublic))
        {
            if (typeof(Delegate).IsAssignableFrom(field.FieldType) || field.Name.Contains(nameof(RobotCursor.Solves), StringComparison.Ordinal))
            {
                continue;
            }
            fields[field.Name] = Entries(field.GetValue(cursor));
        }
        return fields;
    }

    /// <summary>Asserts that two readings hold the same values (value types equal, objects the same instance), naming the fields that differ.</summary>
    internal static void AssertSame(Dictionary<string, object?> expected, Dictionary<string, object?> actual, string what)
    {
        Assert.Equal(expected.Keys.Order(), actual.Keys.Order());
        string[] differ = [.. expected.Keys.Where(name => !Same(expected[name], actual[name])).Order()];
        Assert.True(differ.Length == 0, $"{what}: the cursor's {string.Join(", ", differ)} changed");
    }

    private static object? Entries(object? value) => value switch
    {
        null or string => value,
        IDictionary map => map.Keys.Cast<object>().Select(k => (object?)new Entry(k, map[k])).OrderBy(e => e!.ToString(), StringComparer.Ordinal).ToList(),
        IEnumerable items => items.Cast<object?>().ToList(),
        _ => value,
    };

    private static bool Same(object? a, object? b) => (a, b) switch
    {
        (null, null) => true,
        (List<object?> x, List<object?> y) => x.Count == y.Count && x.Zip(y).All(p => Same(p.First, p.Second)),
        (Entry x, Entry y) => Equals(x.Key, y.Key) && Same(x.Value, y.Value),
        (string x, string y) => x == y,
        (not null, not null) when a.GetType().IsValueType => a.Equals(b),
        _ => ReferenceEquals(a, b),
    };

    /// <summary>One entry of a dictionary field.</summary>
    private sealed record Entry(object Key, object? Value);
}

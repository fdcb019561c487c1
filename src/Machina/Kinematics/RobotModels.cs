namespace Machina;

/// <summary>
/// The built-in catalogue of robot models (read-only). The source of every number is listed in docs/kinematics.md and in each
/// model's <see cref="RobotModel.Source"/>.
/// </summary>
public static class RobotModels
{
    private static readonly RobotModel[] Models = [.. BrandRegistry.Catalogue.SelectMany(b => b.Models())];

    // Names used by earlier versions, kept so that users' code goes on working: old name → catalogue name.
    private static readonly (string Old, string Name)[] Aliases = [("KR 16", "KR 16-2")];

    /// <summary>Every catalogued model.</summary>
    public static IReadOnlyList<RobotModel> All { get; } = Array.AsReadOnly(Models);

    /// <summary>The model with this name (case, spaces, dashes and slashes ignored), or null when there is none.</summary>
    public static RobotModel? Find(string name)
    {
        ArgumentNullException.ThrowIfNull(name);
        string key = Key(name);
        foreach (RobotModel m in Models)
        {
            if (Key(m.Name) == key)
            {
                return m;
            }
        }
        foreach ((string old, string current) in Aliases)
        {
            if (Key(old) == key)
            {
                return Find(current);
            }
        }
        return null;
    }

    /// <summary>The model with this name; throws an <see cref="ArgumentException"/> listing similar names when there is none.</summary>
    public static RobotModel Get(string name)
    {
        RobotModel? m = Find(name);
        if (m is not null)
        {
            return m;
        }
        string key = Key(name);
        var close = Models.Where(x => key.Length > 0 && (Key(x.Name).Contains(key, StringComparison.Ordinal) || key.Contains(Key(x.Name), StringComparison.Ordinal)
                || Key(x.Name).StartsWith(key[..Math.Min(key.Length, 4)], StringComparison.Ordinal)))
            .Select(x => x.Name).ToList();
        string hint = close.Count > 0 ? $"Did you mean: {string.Join(", ", close)}?" : $"Known models: {string.Join(", ", Models.Select(x => x.Name))}.";
        throw new ArgumentException($"There is no robot model called \"{name}\". {hint}", nameof(name));
    }

    private static string Key(string s) =>
        new(s.Where(c => char.IsLetterOrDigit(c) || c == '.').Select(char.ToLowerInvariant).ToArray());
}

using System.Globalization;

namespace Machina;

/// <summary>
/// Reads a maker's table of OPW arms (an embedded text file in the brand's folder, e.g. Brands/Abb/abb-arms.txt): a "brand" line, "source key = text"
/// lines naming the public descriptions, then one arm a line, "name | a1 a2 c1 c2 c3 c4 | lowest joints | highest joints | speeds |
/// source", with "#" comments. More OPW arms (ABB or KUKA joint conventions) are more lines of data, not code.
/// </summary>
internal static class CatalogTable
{
    /// <summary>The arms of the embedded table <paramref name="file"/>, in its order.</summary>
    internal static RobotModel[] Load(string file)
    {
        using Stream stream = typeof(CatalogTable).Assembly.GetManifestResourceStream("Machina.Catalog." + file)
            ?? throw new InvalidOperationException($"The catalogue table {file} is missing from the Machina library.");
        using var reader = new StreamReader(stream);
        return Parse(file, reader.ReadToEnd());
    }

    /// <summary>The arms of a table's text; a malformed line throws, naming the file and the line.</summary>
    internal static RobotModel[] Parse(string file, string text)
    {
        string? brand = null;
        var sources = new Dictionary<string, string>(StringComparer.Ordinal);
        var arms = new List<RobotModel>();
        string[] lines = text.Split('\n');
        for (int i = 0; i < lines.Length; i++)
        {
            string line = lines[i].Trim();
            string where = $"{file}:{i + 1}";
            if (line.Length == 0 || line.StartsWith('#'))
            {
                continue;
            }
            if (line.StartsWith("brand ", StringComparison.Ordinal))
            {
                brand = line["brand ".Length..].Trim();
            }
            else if (line.StartsWith("source ", StringComparison.Ordinal) && line.Contains(" = ", StringComparison.Ordinal))
            {
                int equals = line.IndexOf(" = ", StringComparison.Ordinal);
                sources[line["source ".Length..equals].Trim()] = line[(equals + " = ".Length)..].Trim();
            }
            else
            {
                arms.Add(Arm(brand ?? throw Malformed(where, "an arm comes before the \"brand\" line"), line, sources, where));
            }
        }
        return [.. arms];
    }

    private static RobotModel Arm(string brand, string line, Dictionary<string, string> sources, string where)
    {
        string[] cells = line.Split('|', StringSplitOptions.TrimEntries);
        if (cells.Length != 6)
        {
            throw Malformed(where, $"{cells.Length} columns instead of 6");
        }
        double[] lengths = Numbers(cells[1], where);
        var opw = new OpwParameters(lengths[0], lengths[1], 0, lengths[2], lengths[3], lengths[4], lengths[5]);
        Joints? speeds = cells[4] == "-" ? null : Joints(cells[4], where);
        return RobotModel.FromOpw(cells[0], brand, opw, Joints(cells[2], where), Joints(cells[3], where), speeds, Source(cells[5], sources, where));
    }

    /// <summary>"@key path; note" cites a file of a named description with what was taken from it; any other text stands as written.</summary>
    private static string Source(string cell, Dictionary<string, string> sources, string where)
    {
        if (!cell.StartsWith('@'))
        {
            return cell;
        }
        int space = cell.IndexOf(' ', StringComparison.Ordinal);
        string key = space < 0 ? cell[1..] : cell[1..space];
        if (space < 0 || !sources.TryGetValue(key, out string? repository))
        {
            throw Malformed(where, $"the source \"{cell}\" names no file of a declared description");
        }
        string rest = cell[(space + 1)..];
        int semicolon = rest.IndexOf("; ", StringComparison.Ordinal);
        string path = semicolon < 0 ? rest : rest[..semicolon];
        string note = semicolon < 0 ? "" : $"; {rest[(semicolon + 2)..]}";
        return $"{repository}, {path}: joint origins, limits and velocities{note}";
    }

    private static Joints Joints(string cell, string where)
    {
        double[] v = Numbers(cell, where);
        return new Joints(v[0], v[1], v[2], v[3], v[4], v[5]);
    }

    private static double[] Numbers(string cell, string where)
    {
        string[] words = cell.Split(' ', StringSplitOptions.RemoveEmptyEntries);
        if (words.Length != 6)
        {
            throw Malformed(where, $"\"{cell}\" has {words.Length} numbers instead of 6");
        }
        return [.. words.Select(w => double.TryParse(w, NumberStyles.Float, CultureInfo.InvariantCulture, out double d) && double.IsFinite(d)
            ? d : throw Malformed(where, $"\"{w}\" is not a number"))];
    }

    private static InvalidOperationException Malformed(string where, string what) =>
        new($"The robot catalogue table is malformed at {where}: {what}.");
}

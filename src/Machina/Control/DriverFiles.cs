namespace Machina;

/// <summary>
/// The controller-side driver files shipped in the library (<c>drivers/&lt;brand&gt;/</c>, embedded as
/// <c>Machina.Drivers.&lt;brand&gt;.&lt;file&gt;</c>) and their placeholders (<c>{{HOSTNAME}}</c>, <c>{{PORT}}</c>…). Shared by every brand.
/// </summary>
internal static class DriverFiles
{
    /// <summary>One shipped file of <c>drivers/<paramref name="brand"/>/</c> as embedded, placeholders unfilled.</summary>
    internal static string Read(string brand, string file)
    {
        using Stream stream = typeof(DriverFiles).Assembly.GetManifestResourceStream($"Machina.Drivers.{brand}.{file}")
            ?? throw new InvalidOperationException($"The embedded driver file {file} is missing from the Machina library.");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    }

    /// <summary>One shipped driver file found by its name alone (the file names are unique across brands), placeholders unfilled.</summary>
    internal static string Read(string file)
    {
        string suffix = "." + file;
        string[] names = [.. typeof(DriverFiles).Assembly.GetManifestResourceNames()
            .Where(n => n.StartsWith("Machina.Drivers.", StringComparison.Ordinal) && n.EndsWith(suffix, StringComparison.Ordinal))];
        return names.Length == 1
            ? Read(names[0]["Machina.Drivers.".Length..^suffix.Length], file)
            : throw new InvalidOperationException($"The embedded driver file {file} is {(names.Length == 0 ? "missing from" : "ambiguous in")} the Machina library.");
    }

    /// <summary><paramref name="text"/> with every <c>{{NAME}}</c> of <paramref name="values"/> replaced by its value.</summary>
    internal static string Fill(string text, params (string Name, string Value)[] values)
    {
        foreach ((string name, string value) in values)
        {
            text = text.Replace("{{" + name + "}}", value, StringComparison.Ordinal);
        }
        return text;
    }
}

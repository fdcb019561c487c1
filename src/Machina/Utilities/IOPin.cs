namespace Machina;

/// <summary>Rules for IO pin names: a whole number ("2") or a signal name ("DO_15").</summary>
internal static class IOPin
{
    /// <summary>Refuses null, empty, or names with quotes, spaces or control characters.</summary>
    internal static string Validate(string? pin)
    {
        if (string.IsNullOrWhiteSpace(pin))
        {
            throw new ArgumentException("An IO pin needs a number (\"2\") or a signal name (\"DO_15\").", nameof(pin));
        }
        foreach (char c in pin)
        {
            if (!(char.IsLetterOrDigit(c) || c == '_' || c == '-' || c == '.'))
            {
                throw new ArgumentException($"IO pin \"{pin}\" contains '{c}'; use letters, digits, '_', '-' or '.'.", nameof(pin));
            }
        }
        return pin;
    }

    /// <summary>True when the pin is a non-negative whole number.</summary>
    internal static bool TryNumber(string pin, out int number) =>
        int.TryParse(pin, System.Globalization.NumberStyles.None, Num.Inv, out number);

    /// <summary>The pin as instruction text: the number as written (so "02" stays "02" and parses back the same), or the name in quotes.</summary>
    internal static string Text(string pin) => TryNumber(pin, out _) ? pin : "\"" + pin + "\"";
}

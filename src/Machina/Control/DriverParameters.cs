using System.Globalization;

namespace Machina;

/// <summary>Reads the parameters of <c>GetDeviceDriverModules</c> (HOSTNAME, PORT…) with clear errors; shared by every brand.</summary>
internal static class DriverParameters
{
    /// <summary>A required, non-blank parameter, trimmed.</summary>
    internal static string Require(IReadOnlyDictionary<string, string> parameters, string key) =>
        parameters.TryGetValue(key, out string? value) && !string.IsNullOrWhiteSpace(value)
            ? value.Trim()
            : throw new ArgumentException($"The driver modules need \"{key}\" (HOSTNAME: the address the driver uses, PORT: its port).", nameof(parameters));

    /// <summary>The required PORT parameter, a whole number.</summary>
    internal static int Port(IReadOnlyDictionary<string, string> parameters)
    {
        string text = Require(parameters, "PORT");
        return int.TryParse(text, NumberStyles.None, Num.Inv, out int port)
            ? port
            : throw new ArgumentException($"PORT must be a whole number, not \"{text}\".", nameof(parameters));
    }

    /// <summary>An optional number, or <paramref name="fallback"/> when absent.</summary>
    internal static double Number(IReadOnlyDictionary<string, string> parameters, string key, double fallback, string meaning)
    {
        if (!parameters.TryGetValue(key, out string? text))
        {
            return fallback;
        }
        return double.TryParse(text, NumberStyles.Float, Num.Inv, out double value)
            ? value
            : throw new ArgumentException($"{key} must be {meaning}, not \"{text}\".", nameof(parameters));
    }
}

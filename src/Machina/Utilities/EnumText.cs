using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Case-insensitive enum parsing with error messages that list the accepted names.</summary>
internal static class EnumText
{
    /// <summary>Parses a name case-insensitively; numbers are refused. Throws an error listing the accepted names.</summary>
    /// <remarks>The error's <see cref="ArgumentException.ParamName"/> is the caller's argument (its parameter name, e.g. "mode").</remarks>
    internal static T Parse<T>(string? text, string what, [CallerArgumentExpression(nameof(text))] string paramName = "") where T : struct, Enum
    {
        if (TryParse<T>(text, out var value))
        {
            return value;
        }
        throw new ArgumentException($"\"{text}\" is not a valid {what}; use one of: {string.Join(", ", Enum.GetNames<T>())}.", paramName);
    }

    /// <summary>Parses a single member name case-insensitively; numbers and comma lists are refused.</summary>
    internal static bool TryParse<T>(string? text, out T value) where T : struct, Enum
    {
        value = default;
        if (string.IsNullOrWhiteSpace(text))
        {
            return false;
        }
        string trimmed = text.Trim();
        // Numbers and comma lists ("Linear, Joint", which .NET would OR together) name no single member.
        if (char.IsDigit(trimmed[0]) || trimmed[0] == '-' || trimmed[0] == '+' || trimmed.Contains(','))
        {
            return false;
        }
        return Enum.TryParse(trimmed, ignoreCase: true, out value) && Enum.IsDefined(value);
    }

    /// <summary>Refuses enum values that name no member (e.g. <c>(MotionType)7</c>).</summary>
    internal static T RequireDefined<T>(T value, string name) where T : struct, Enum
    {
        if (!Enum.IsDefined(value))
        {
            throw new ArgumentException($"{value} is not a valid {typeof(T).Name}; use one of: {string.Join(", ", Enum.GetNames<T>())}.", name);
        }
        return value;
    }
}

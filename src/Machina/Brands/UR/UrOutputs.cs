namespace Machina;

/// <summary>
/// The outputs a UR robot has, and why an I/O action cannot run on one: one rule set for the URScript compiler (which writes
/// <c># NOT SUPPORTED ON UR</c> instead) and the online driver (which refuses the action when it is issued).
/// </summary>
internal static class UrOutputs
{
    /// <summary>Standard digital outputs 0 to 7.</summary>
    public const int StandardDigital = 8;

    /// <summary>Tool digital outputs 0 and 1.</summary>
    public const int ToolDigital = 2;

    /// <summary>Standard analog outputs 0 and 1.</summary>
    public const int StandardAnalog = 2;

    /// <summary>Why a UR cannot set this digital output, or null when it can.</summary>
    public static string? WhyNot(ActionIODigital io) =>
        PinProblem(io.PinName, io.IsToolPin ? ToolDigital : StandardDigital, io.IsToolPin, "digital");

    /// <summary>Why a UR cannot set this analog output to this value, or null when it can.</summary>
    public static string? WhyNot(ActionIOAnalog io)
    {
        if (io.IsToolPin)
        {
            return "the UR tool flange has no analog outputs (only analog inputs).";
        }
        if (PinProblem(io.PinName, StandardAnalog, false, "analog") is string problem)
        {
            return problem;
        }
        return io.Value is >= 0 and <= 1
            ? null
            : $"UR analog outputs take a value from 0 to 1 (a fraction of the output's current or voltage range), not {Num.G(io.Value)}.";
    }

    private static string? PinProblem(string pin, int count, bool tool, string kind)
    {
        string where = tool ? "tool " : "standard ";
        if (!IOPin.TryNumber(pin, out int n))
        {
            return $"UR {kind} outputs are numbered; \"{pin}\" is not a number (use 0 to {count - 1}).";
        }
        return n < count ? null : $"UR robots have {where}{kind} outputs 0 to {count - 1}; output {n} does not exist.";
    }
}

namespace Machina;

/// <summary>
/// The digital inputs a UR robot has (standard 0–7, tool 0–1), how a program reads one, and why a wait cannot run on one:
/// one rule set for the URScript compiler and the online driver.
/// </summary>
internal static class UrInputs
{
    /// <summary>Standard digital inputs 0 to 7.</summary>
    public const int StandardDigital = 8;

    /// <summary>Tool digital inputs 0 and 1.</summary>
    public const int ToolDigital = 2;

    /// <summary>Why a UR cannot wait for this input, or null when it can.</summary>
    public static string? WhyNot(ActionWaitDigital wait)
    {
        int count = wait.IsToolPin ? ToolDigital : StandardDigital;
        string where = wait.IsToolPin ? "tool " : "standard ";
        if (!IOPin.TryNumber(wait.PinName, out int n))
        {
            return $"UR digital inputs are numbered; \"{wait.PinName}\" is not a number (use 0 to {count - 1}).";
        }
        return n < count ? null : $"UR robots have {where}digital inputs 0 to {count - 1}; input {n} does not exist.";
    }

    /// <summary>Standard analog inputs 0 and 1; the tool has analog inputs 0 and 1 too.</summary>
    public const int Analog = 2;

    /// <summary>Why a UR cannot read this input, or null when it can.</summary>
    public static string? WhyNot(ActionReadInput read)
    {
        int count = read.IsAnalog ? Analog : read.IsToolPin ? ToolDigital : StandardDigital;
        string what = (read.IsToolPin ? "tool " : "standard ") + (read.IsAnalog ? "analog" : "digital");
        if (!IOPin.TryNumber(read.PinName, out int n))
        {
            return $"UR inputs are numbered; \"{read.PinName}\" is not a number (use 0 to {count - 1}).";
        }
        return n < count ? null : $"UR robots have {what} inputs 0 to {count - 1}; input {n} does not exist.";
    }

    /// <summary>The URScript call that reads an input: get_standard_digital_in, get_tool_digital_in, get_standard_analog_in or get_tool_analog_in.</summary>
    public static string ReadCall(ActionReadInput read) =>
        "get_" + (read.IsToolPin ? "tool" : "standard") + (read.IsAnalog ? "_analog_in(" : "_digital_in(") + Num.I(read.PinNumber) + ")";

    /// <summary>The URScript call that reads the input: <c>get_standard_digital_in(n)</c> or <c>get_tool_digital_in(n)</c>.</summary>
    public static string ReadCall(ActionWaitDigital wait) =>
        (wait.IsToolPin ? "get_tool_digital_in(" : "get_standard_digital_in(") + Num.I(wait.PinNumber) + ")";

    /// <summary>What the program shows when the wait times out.</summary>
    public static string TimeoutText(ActionWaitDigital wait) =>
        $"{(wait.IsToolPin ? "Tool digital" : "Digital")} input {Num.I(wait.PinNumber)} did not turn {(wait.On ? "on" : "off")} within {ProgramText.Seconds(wait.TimeoutMillis)} s";
}

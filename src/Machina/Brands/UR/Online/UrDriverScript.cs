namespace Machina;

/// <summary>Machina's URScript driver (drivers/ur/machina_ur_driver.script), embedded in the library, with the host's address filled in.</summary>
internal static class UrDriverScript
{
    /// <summary>The file name of the driver program.</summary>
    public const string FileName = "machina_ur_driver.script";

    /// <summary>The version the script declares.</summary>
    public const string Version = "3.0.0";

    /// <summary>
    /// How long the driver waits for an instruction's values after its header before it takes the stream as broken (and
    /// halts, docs/protocol-ur.md §2): 5 s.
    /// </summary>
    public static readonly TimeSpan DefaultValuesTimeout = TimeSpan.FromSeconds(5);

    /// <summary>
    /// The script with <c>{{HOSTNAME}}</c> and <c>{{PORT}}</c> replaced (where it connects back to), <c>{{INSTANCE}}</c>, the
    /// number the program publishes in RTDE output_int_register_26 when it starts, and <c>{{VALUES_TIMEOUT}}</c>, the seconds
    /// an instruction's values may take after its header (<paramref name="valuesTimeout"/>, default
    /// <see cref="DefaultValuesTimeout"/>, whole milliseconds). It begins with its <c>def</c> and ends with its <c>end</c> and a
    /// line break, as the script manual asks.
    /// </summary>
    public static string For(string hostname, int port, int instance = 1, TimeSpan? valuesTimeout = null)
    {
        ArgumentException.ThrowIfNullOrWhiteSpace(hostname);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(port);
        ArgumentOutOfRangeException.ThrowIfNegativeOrZero(instance);
        long milliseconds = (long)Math.Round((valuesTimeout ?? DefaultValuesTimeout).TotalMilliseconds);
        // 0 or less would never time out (script manual): a stalled stream would then hold the program for ever.
        ArgumentOutOfRangeException.ThrowIfLessThan(milliseconds, 1L, nameof(valuesTimeout));
        if (hostname.Contains('"', StringComparison.Ordinal) || hostname.Contains('\n', StringComparison.Ordinal))
        {
            throw new ArgumentException($"\"{hostname}\" is not a host name or address.", nameof(hostname));
        }
        return DriverFiles.Fill(DriverFiles.Read("ur", FileName).Replace("\r\n", "\n", StringComparison.Ordinal),
            ("HOSTNAME", hostname.Trim()), ("PORT", port.ToString(Num.Inv)), ("INSTANCE", instance.ToString(Num.Inv)),
            ("VALUES_TIMEOUT", (milliseconds / 1000.0).ToString("0.0##", Num.Inv)));
    }
}

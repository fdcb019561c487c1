namespace Machina.Simulation;

/// <summary>A fault a virtual controller can inject right after it acknowledges an executed request (docs/simulation.md).</summary>
public enum VirtualFault
{
    /// <summary>Nothing: the acknowledgement goes out as usual.</summary>
    None,

    /// <summary>The acknowledgement goes out, then the driver connection is closed; the controller runs on what it holds.</summary>
    Drop,

    /// <summary>The acknowledgement goes out late, after <see cref="VirtualFaults.Delay"/> on the controller's clock.</summary>
    Delay,

    /// <summary>Bytes outside the protocol go out before the acknowledgement (the brand decides what its host cannot read).</summary>
    Garbage,

    /// <summary>Only the first part of the acknowledgement goes out, then the connection is closed.</summary>
    Truncate,

    /// <summary>An acknowledgement of an id never sent goes out before the real one.</summary>
    UnknownAcknowledgement,

    /// <summary>The acknowledgement goes out, then the controller stops executing and answering until <c>ResumeAnswering</c>.</summary>
    StopAnswering,

    /// <summary>The acknowledgement goes out, the connection closes and nothing runs for <see cref="VirtualFaults.Delay"/>; what was received is kept.</summary>
    RestartKeepingBuffer,

    /// <summary>
    /// The acknowledgement goes out, the connection closes and every request received but not executed is lost; the driver's
    /// progress (last executed id) survives, so a host that reconnects sends the lost requests again.
    /// </summary>
    RestartLosingBuffer,

    /// <summary>The acknowledgement goes out, then a protective stop (UR only; other brands cannot report one and ignore it).</summary>
    ProtectiveStop,

    /// <summary>
    /// The acknowledgement goes out, then the controller restarts as after a power cycle or a reloaded program: the connection
    /// closes, every request received but not executed is lost, and the driver program starts again from its beginning with
    /// its progress forgotten (it reports 0 executed, 0 received). The host cannot learn which of its unconfirmed requests ran.
    /// </summary>
    RestartLosingProgress,
}

/// <summary>
/// Faults a virtual controller injects by itself, deterministically: the same seed and the same requests give the same faults
/// at the same acknowledgements. Set it as the controller options' <c>Faults</c>; the default injects nothing.
/// </summary>
public sealed record VirtualFaults
{
    /// <summary>Seed of the controller's random choices (which acknowledgement, which fault, where to cut). Default 0.</summary>
    public int Seed { get; init; }

    /// <summary>Chance, from 0 to 1, that a fault follows any one acknowledgement. Default 0 (never).</summary>
    public double Chance { get; init; }

    /// <summary>The faults drawn from (each equally likely) when <see cref="Chance"/> or <see cref="After"/> strikes. Default: <see cref="VirtualFault.Drop"/>.</summary>
    public IReadOnlyList<VirtualFault> Kinds { get; init; } = [VirtualFault.Drop];

    /// <summary>Injects one fault right after this many acknowledgements (counted from the start), whatever <see cref="Chance"/> says. 0 = never. Default 0.</summary>
    public int After { get; init; }

    /// <summary>How late a <see cref="VirtualFault.Delay"/> acknowledgement goes out, and how long a restart keeping its buffer takes. Default 10 ms.</summary>
    public TimeSpan Delay { get; init; } = TimeSpan.FromMilliseconds(10);

    /// <summary>How many connection attempts are refused (accepted and closed at once) before the controller serves one. Default 0.</summary>
    public int RefuseConnections { get; init; }

    /// <summary>Throws <see cref="ArgumentException"/> naming the first setting that cannot work.</summary>
    internal void Validate()
    {
        if (!(Chance is >= 0 and <= 1))
        {
            throw new ArgumentException("Faults.Chance must be between 0 and 1.", nameof(Chance));
        }
        ArgumentNullException.ThrowIfNull(Kinds);
        if ((Chance > 0 || After > 0) && Kinds.Count == 0)
        {
            throw new ArgumentException("Faults.Kinds must name at least one fault when Chance or After is set.", nameof(Kinds));
        }
        if (Kinds.Any(k => !Enum.IsDefined(k)))
        {
            throw new ArgumentException("Faults.Kinds holds a value that is not a VirtualFault.", nameof(Kinds));
        }
        if (After < 0 || RefuseConnections < 0)
        {
            throw new ArgumentException("Faults.After and Faults.RefuseConnections cannot be negative.");
        }
        if (Delay < TimeSpan.Zero || Delay > TimeSpan.FromHours(1))
        {
            throw new ArgumentException("Faults.Delay must be between 0 and 1 hour.", nameof(Delay));
        }
    }
}

namespace Machina;

/// <summary>Codes of data messages (<c>$code …;</c>) sent by the RAPID driver and monitor to the host (spec online §6.4).</summary>
internal enum AbbResponseCode
{
    Version = 20,
    Pose = 21,
    Joints = 22,
    ExternalAxes = 23,
    FullPose = 24,

    /// <summary>Handshake, driver 1.6 on: <c>$25 lastExecutedId lastReceivedId;</c>, so a reconnecting host sends nothing twice.</summary>
    Progress = 25,

    /// <summary><c>$26 id code;</c>, the request with that id could not run and the driver stopped (<see cref="AbbFailure"/>).</summary>
    Failure = 26,

    /// <summary><c>$27 id value;</c>, driver 1.7 on: the value read by the read request with that id, sent just before its acknowledgement.</summary>
    InputRead = 27,

    /// <summary><c>$28 n;</c> from the monitor task: it did the host's out-of-band command (1 paused, 2 resumed, 3 stopped).</summary>
    Control = 28,
}

namespace Machina;

/// <summary>The driver executed the request with this id (and instruction code).</summary>
internal readonly record struct AbbAcknowledgement(int Id, int Code);

/// <summary>Version the RAPID driver reports in its handshake (<c>$20 major minor patch;</c>).</summary>
internal readonly record struct AbbDriverVersion(int Major, int Minor, int Patch)
{
    /// <summary>True when the host can talk to this driver: same major version, minor at least the shipped one's (<see cref="AbbDriver.Requirement"/>; fix of bug A5).</summary>
    public bool IsSupported => AbbDriver.Requirement.Accepts(ToVersion());

    /// <summary>The version as a <see cref="Version"/>.</summary>
    public Version ToVersion() => new(Major, Minor, Patch);

    /// <summary>True when the handshake of this driver ends with its progress (<c>$25</c>, from 1.6).</summary>
    public bool ReportsProgress => Major == 1 && Minor >= 6;

    /// <inheritdoc/>
    public override string ToString() => $"{Major}.{Minor}.{Patch}";
}

/// <summary>A Cartesian pose from the driver: position in mm and orientation.</summary>
internal readonly record struct AbbPose(Vector Position, Rotation Rotation);

/// <summary>One periodic state report of the monitor task (<c>$24</c>): TCP pose, joints and external axes.</summary>
internal readonly record struct AbbMonitorUpdate(Vector Position, Rotation Rotation, Joints Joints, ExternalAxes ExternalAxes);

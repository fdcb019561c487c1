namespace Machina.Simulation.Rapid;

/// <summary>
/// The controller's active world zones (RAPID World Zones: WZLimSup, WZDOSet): one set for the robot, whichever task activated them.
/// </summary>
internal sealed partial class RapidTwinController
{
    private readonly Lock _zoneGate = new();
    private volatile RapidWorldZone[] _zones = [];

    /// <summary>True while a world zone is active.</summary>
    internal bool HasZones => _zones.Length > 0;

    /// <summary>Activates <paramref name="zone"/> (again, with its new shape, when it was active).</summary>
    internal void Activate(RapidWorldZone zone)
    {
        lock (_zoneGate)
        {
            _zones = [.. _zones.Where(z => z != zone), zone];
        }
        UpdateZoneOutputs(Arm.Tcp.Position, Arm.Joints);
    }

    /// <summary>WZFree: the zone is no longer supervised.</summary>
    internal void Free(RapidWorldZone zone)
    {
        lock (_zoneGate)
        {
            _zones = [.. _zones.Where(z => z != zone)];
        }
    }

    /// <summary>The first enabled limit zone (WZLimSup) that the arm at any of <paramref name="points"/> (TCP and joints) would be in, or null.</summary>
    internal RapidWorldZone? LimitZoneOn(IEnumerable<(Vector Tcp, Joints Joints)> points)
    {
        RapidWorldZone[] zones = _zones;
        if (!zones.Any(z => z.Limits))
        {
            return null;
        }
        foreach ((Vector tcp, Joints joints) in points)
        {
            if (zones.FirstOrDefault(z => z.Limits && z.Enabled && z.Shape!.Contains(tcp, joints)) is { } hit)
            {
                return hit;
            }
        }
        return null;
    }

    /// <summary>Sets the outputs of the enabled WZDOSet zones for a TCP at <paramref name="tcp"/>, the arm at <paramref name="joints"/>.</summary>
    internal void UpdateZoneOutputs(Vector tcp, Joints joints)
    {
        foreach (RapidWorldZone zone in _zones)
        {
            if (zone is { Enabled: true, Output: (_, int index, bool inside) })
            {
                SetBit("do", index, zone.Shape!.Contains(tcp, joints) ? inside : !inside);
            }
        }
    }
}

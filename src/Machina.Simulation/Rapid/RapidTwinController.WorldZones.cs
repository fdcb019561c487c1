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
        UpdateZoneOutputs(Arm.Tcp.Position);
    }

    /// <summary>WZFree: the zone is no longer supervised.</summary>
    internal void Free(RapidWorldZone zone)
    {
        lock (_zoneGate)
        {
            _zones = [.. _zones.Where(z => z != zone)];
        }
    }

    /// <summary>The first enabled limit zone (WZLimSup) that a TCP at any of <paramref name="points"/> would be in, or null.</summary>
    internal RapidWorldZone? LimitZoneOn(IEnumerable<Vector> points)
    {
        RapidWorldZone[] zones = _zones;
        if (!zones.Any(z => z.Limits))
        {
            return null;
        }
        foreach (Vector p in points)
        {
            if (zones.FirstOrDefault(z => z.Limits && z.Enabled && z.Shape!.Contains(p)) is { } hit)
            {
                return hit;
            }
        }
        return null;
    }

    /// <summary>Sets the outputs of the enabled WZDOSet zones for a TCP at <paramref name="tcp"/>.</summary>
    internal void UpdateZoneOutputs(Vector tcp)
    {
        foreach (RapidWorldZone zone in _zones)
        {
            if (zone is { Enabled: true, Output: (_, int index, bool inside) })
            {
                SetBit("do", index, zone.Shape!.Contains(tcp) ? inside : !inside);
            }
        }
    }
}

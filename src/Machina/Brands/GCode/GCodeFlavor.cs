namespace Machina;

/// <summary>
/// What differs between the G-code dialects Machina writes: the ZMorph printers of the original library, and generic
/// Marlin-firmware printers. Everything else (units mm, mm/min, ms, °C; absolute positions and extrusion) is shared.
/// </summary>
internal sealed class GCodeFlavor
{
    private GCodeFlavor() { }

    /// <summary>The language this flavour is compiled for.</summary>
    internal RobotType Brand { get; private init; }

    /// <summary>Mode lines at the top of every file (no motion, no heating).</summary>
    internal string[] Preamble { get; private init; } = [];

    /// <summary>Lines written by <c>Initialize()</c>; they end with the extruder position set to 0.</summary>
    internal string[] StartSequence { get; private init; } = [];

    /// <summary>Lines written by <c>Terminate()</c> before the nozzle leaves the print (e.g. pulling the filament back).</summary>
    internal string[] EndRetract { get; private init; } = [];

    /// <summary>
    /// Where <c>Terminate()</c> parks the nozzle, X and Y in mm (null: it stays above the print). The nozzle first rises straight up
    /// to <see cref="ParkMinZ"/> or <see cref="GCodeWriter.ClearanceMm"/> above the highest point reached, whichever is higher.
    /// </summary>
    internal (double X, double Y)? ParkXY { get; private init; }

    /// <summary>Lowest park height, mm (the original ZMorph ending parked at this fixed height whatever the print's height).</summary>
    internal double ParkMinZ { get; private init; } = double.NegativeInfinity;

    /// <summary>Lines written by <c>Terminate()</c> after parking: heaters, fans and motors off.</summary>
    internal string[] EndShutdown { get; private init; } = [];

    /// <summary>True when <see cref="EndRetract"/> sets the extruder position to 0.</summary>
    internal bool EndResetsExtruder { get; private init; }

    /// <summary>True: the feed rate goes on the motion lines (<c>G1 X… F…</c>); false: it is its own line (<c>G1 F…</c>) when it changes.</summary>
    internal bool FeedOnMotionLine { get; private init; }

    /// <summary>Code of motions that do not extrude: <c>G0</c> (Marlin) or <c>G1</c>.</summary>
    internal string TravelCode { get; private init; } = "G1";

    /// <summary>When the extruder position would pass this many mm, it is first set back to 0 (<c>G92 E0</c>); infinity for never.</summary>
    internal double ExtrusionResetLimit { get; private init; } = double.PositiveInfinity;

    /// <summary><c>S</c> value that turns a digital output on.</summary>
    internal string DigitalOnValue { get; private init; } = "1";

    /// <summary>True when the firmware sets accelerations with <c>M204</c>.</summary>
    internal bool SupportsAcceleration { get; private init; }

    /// <summary>True when the firmware draws arcs in the XY plane with <c>G2</c>/<c>G3</c>; other arcs become straight segments.</summary>
    internal bool SupportsArcs { get; private init; }

    /// <summary>Makes the line that shows a text (already made safe) on the printer's screen.</summary>
    internal Func<string, string> MessageLine { get; private init; } = text => "; " + text;

    /// <summary>ZMorph printers, as the original Machina wrote for them.</summary>
    internal static GCodeFlavor ZMorph { get; } = new()
    {
        Brand = RobotType.ZMORPH,
        Preamble = ["G90", "M82", "G92 E0"],
        StartSequence =
        [
            "G91", "G1 Z1.000 F200.000", "G90", "G28 X0.000 Y0.00", "G1 X117.500 Y125.000 F8000.000", "G28 Z0.000", "G92 E0.00000", "M82",
        ],
        // The original ended with "G1 X117.500 Y220.000 Z30.581 F300.000": a diagonal move that went down through any print
        // taller than 30 mm. Machina rises first, then travels to the same park position.
        EndRetract = ["G92 E0.0000", "G91", "G1 E-3.00000 F1800.000", "G90", "G92 E0.00000"],
        ParkXY = (117.5, 220),
        ParkMinZ = 30.581,
        EndShutdown = ["T0", "M104 S0", "T1", "M104 S0", "M140 S0", "M106 S0", "M84", "M220 S100"],
        EndResetsExtruder = true,
        FeedOnMotionLine = false,
        TravelCode = "G1",
        ExtrusionResetLimit = 10,
        DigitalOnValue = "1",
        MessageLine = text => "M70 P1000 (" + text + ")",
    };

    /// <summary>Generic printers running Marlin firmware (version 2 and later).</summary>
    internal static GCodeFlavor Marlin { get; } = new()
    {
        Brand = RobotType.MARLIN,
        Preamble = ["G21", "G90", "M82", "G92 E0"],
        StartSequence = ["G28", "G92 E0"],
        EndShutdown = ["M104 S0", "M140 S0", "M107", "M84"],
        FeedOnMotionLine = true,
        TravelCode = "G0",
        DigitalOnValue = "255",
        SupportsAcceleration = true,
        SupportsArcs = true,
        MessageLine = text => "M117 " + text,
    };
}

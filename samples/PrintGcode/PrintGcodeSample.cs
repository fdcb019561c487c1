// A small 3D print for a ZMorph (or, with --printer marlin, any Marlin printer): a square "vase" printed as one continuous
// spiral, the way slicers print vases. The nozzle climbs a little along every side, so there is no seam between layers.
// Machina writes the G-code file; this sample prints where it is, how long it is and its first lines. No printer needed:
// send the file to your printer (SD card, OctoPrint, the printer's own software) when you are happy with it.
//
// Usage: dotnet run --project samples/PrintGcode [--printer zmorph|marlin] [--layers N] [--out folder]
//
// The numbers a designer may want to change are at the top of RunAsync: the size of the square, the layer height, the
// temperatures, the speeds and the extrusion rate (millimetres of filament pushed per millimetre the nozzle travels).
using System.Globalization;

namespace Machina.Samples;

/// <summary>The G-code print sample (the test suite runs it through <see cref="RunAsync"/>).</summary>
public static class PrintGcodeSample
{
    /// <summary>Runs the sample: 0 when the G-code was written and looks right, 1 when it does not, 2 for wrong arguments.</summary>
    public static Task<int> RunAsync(string[] args, TextWriter output, TextWriter error, CancellationToken cancellationToken)
    {
        const double side = 30;            // mm, the square's side
        const double layerHeight = 0.2;    // mm
        const double centreX = 100, centreY = 100;   // mm, where on the bed
        const double bedTemperature = 60, nozzleTemperature = 210;   // °C, for PLA
        const double travelSpeed = 80, printSpeed = 25;              // mm/s
        // Filament (1.75 mm) per mm of path for a 0.4 mm wide, 0.2 mm high line: 0.4 × 0.2 / (π × 0.875²) ≈ 0.033.
        const double extrusionRate = 0.033;

        RobotType printer = RobotType.ZMORPH;
        int layers = 5;
        string folder = Path.Combine(Path.GetTempPath(), "MachinaPrint");
        for (int i = 0; i < args.Length; i += 2)
        {
            string? value = i + 1 < args.Length ? args[i + 1] : null;
            bool known = value is not null && args[i] switch
            {
                "--printer" => Enum.TryParse(value, ignoreCase: true, out printer) && printer is RobotType.ZMORPH or RobotType.MARLIN,
                "--layers" => int.TryParse(value, NumberStyles.None, CultureInfo.InvariantCulture, out layers) && layers is >= 1 and <= 500,
                "--out" => (folder = value).Length > 0,
                _ => false,
            };
            if (!known)
            {
                error.WriteLine("Usage: PrintGcode [--printer zmorph|marlin] [--layers 1..500] [--out <folder>]");
                return Task.FromResult(SampleHost.Usage);
            }
        }

        var printerBot = Robot.Create("SquareVase", printer);
        printerBot.Initialize();                                          // home the axes
        printerBot.TemperatureTo(bedTemperature, "bed", false);           // start heating the bed, don't wait
        printerBot.TemperatureTo(nozzleTemperature, "extruder", true);    // heat the nozzle and wait for it
        printerBot.SpeedTo(travelSpeed);
        printerBot.MoveTo(centreX - side / 2, centreY - side / 2, layerHeight);   // the first corner, one layer above the bed
        printerBot.ExtrusionRateTo(extrusionRate);
        printerBot.SpeedTo(printSpeed);
        printerBot.Extrude(true);
        // The first layer flat, so the vase has a closed outline on the bed…
        printerBot.Move(side, 0, 0);
        printerBot.Move(0, side, 0);
        printerBot.Move(-side, 0, 0);
        printerBot.Move(0, -side, 0);
        // …then one layer height per turn, a quarter on each side.
        for (int layer = 1; layer < layers; layer++)
        {
            cancellationToken.ThrowIfCancellationRequested();
            printerBot.Move(side, 0, layerHeight / 4);
            printerBot.Move(0, side, layerHeight / 4);
            printerBot.Move(-side, 0, layerHeight / 4);
            printerBot.Move(0, -side, layerHeight / 4);
        }
        printerBot.Extrude(false);
        printerBot.SpeedTo(travelSpeed);
        printerBot.Move(0, 0, 10);          // lift the nozzle off the print
        printerBot.TemperatureTo(0, "extruder", false);
        printerBot.TemperatureTo(0, "bed", false);
        printerBot.Terminate();             // park and switch off

        RobotProgram program = printerBot.Compile();
        IReadOnlyList<string> written = program.SaveToFolder(folder);
        RobotProgramFile gcode = program.MainFile;
        output.WriteLine($"Wrote {string.Join(", ", written)} for a {printer} printer.");

        // A summary read back from the G-code itself.
        IReadOnlyList<string> lines = gcode.Lines;
        // An extruding move goes somewhere (X or Y) and pushes filament (E); a lone E is a retraction.
        string[] printing = [.. lines.Where(l => IsMove(l) && Word(l, 'E') is not null && (Word(l, 'X') ?? Word(l, 'Y')) is not null)];
        int extrudingMoves = printing.Length;
        double top = printing.Select(l => Word(l, 'Z')).OfType<double>().DefaultIfEmpty(0).Max();
        output.WriteLine($"{lines.Count} lines, {layers} layers of {Num(layerHeight)} mm ({Num(side)} mm square, printed up to Z {Num(top)} mm), " +
            $"{extrudingMoves} extruding moves.");
        foreach (ProgramWarning warning in program.Warnings)
        {
            output.WriteLine($"warning: {warning}");
        }
        // The start of the file, down to the first line that prints (homing, heating, the first move).
        int firstPrinting = printing.Length > 0 ? lines.ToList().IndexOf(printing[0]) : 20;
        output.WriteLine("First lines:");
        foreach (string line in lines.Take(Math.Min(firstPrinting + 1, 40)))
        {
            output.WriteLine("  " + line);
        }

        // Refuse to call it a success if the file would not print.
        if (!lines.Any(l => l.StartsWith("M109 ", StringComparison.Ordinal)))
        {
            return Task.FromResult(SampleHost.Fail(error, "the G-code never waits for the nozzle to heat (M109)."));
        }
        double expectedTop = layers * layerHeight;
        if (extrudingMoves != 4 * layers || Math.Abs(top - expectedTop) > 0.001)
        {
            return Task.FromResult(SampleHost.Fail(error, $"expected {4 * layers} extruding moves up to Z {Num(expectedTop)}, found {extrudingMoves} up to Z {Num(top)}."));
        }
        return Task.FromResult(SampleHost.Ok);
    }

    private static bool IsMove(string line) => line.StartsWith("G1 ", StringComparison.Ordinal) || line.StartsWith("G0 ", StringComparison.Ordinal);

    /// <summary>The number after a letter in a G-code line (e.g. the Z of <c>G1 X10 Z0.4</c>), or null.</summary>
    private static double? Word(string line, char letter)
    {
        int comment = line.IndexOf(';', StringComparison.Ordinal);
        foreach (string word in (comment < 0 ? line : line[..comment]).Split(' ', StringSplitOptions.RemoveEmptyEntries))
        {
            if (word.Length > 1 && word[0] == letter && double.TryParse(word.AsSpan(1), NumberStyles.Float, CultureInfo.InvariantCulture, out double value))
            {
                return value;
            }
        }
        return null;
    }

    private static string Num(double value) => value.ToString("0.###", CultureInfo.InvariantCulture);
}

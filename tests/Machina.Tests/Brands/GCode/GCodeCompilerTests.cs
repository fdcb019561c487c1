using System.Globalization;
using Machina.Tests.Brands.Kuka;
using Machina.Tests.Support;

namespace Machina.Tests.Brands.GCode;

public class GCodeCompilerTests
{
    private static Robot NewBot(RobotType brand) => Robot.Create("Test", brand);

    private static RobotProgram Compile(Robot bot, RobotType brand, bool human = false) =>
        bot.Compile(brand, new CompileOptions { HumanComments = human });

    /// <summary>The lines after the header and preamble (which end at the first empty line after the header's blank line).</summary>
    private static string[] Body(Robot bot, RobotType brand, bool human = false)
    {
        var lines = Compile(bot, brand, human).Files[0].Lines.ToList();
        int headerEnd = lines.IndexOf("");
        int preambleEnd = lines.IndexOf("", headerEnd + 1);
        return lines.Skip(preambleEnd + 1).ToArray();
    }

    /// <summary>A new printer of <paramref name="brand"/> at (x, y, z), extruding <paramref name="rate"/> mm of filament per mm.</summary>
    private static Robot Extruding(RobotType brand, double x, double y, double z, double rate)
    {
        var bot = NewBot(brand);
        bot.MoveTo(x, y, z);
        bot.ExtrusionRateTo(rate);
        bot.Extrude();
        return bot;
    }

    [Fact]
    public void Compile_Preamble_SetsAbsoluteModesAndZeroesTheExtruder()
    {
        var zmorph = Compile(NewBot(RobotType.ZMORPH), RobotType.ZMORPH).Files[0].Lines;
        var marlin = Compile(NewBot(RobotType.MARLIN), RobotType.MARLIN).Files[0].Lines;

        Assert.Equal(["G90", "M82", "G92 E0", ""], zmorph.SkipWhile(l => l.StartsWith(';')).Skip(1));
        Assert.Equal(["G21", "G90", "M82", "G92 E0", ""], marlin.SkipWhile(l => l.StartsWith(';')).Skip(1));
    }

    /// <summary>Spec 14.3's example: extrusion rate 0.6, then extruded moves of 10, 10 and 20 mm.</summary>
    private static Robot ExtrudeTenTenTwenty(RobotType brand)
    {
        var bot = Extruding(brand, 0, 0, 1, 0.6);
        bot.Move(10, 0, 0);
        bot.Move(10, 0, 0);
        bot.Move(20, 0, 0);
        return bot;
    }

    [Fact]
    public void Compile_ZMorphExtrusionPastTenMillimetres_HomesTheExtruderAsTheSpecExample()
    {
        Robot bot = ExtrudeTenTenTwenty(RobotType.ZMORPH);

        Assert.Equal(
            [
                "G1 F1200",
                "G1 X0 Y0 Z1",
                "G1 X10 Y0 Z1 E6",
                "; Homing extrusion length after 6 mm (10 mm limit)",
                "G92 E0.0000",
                "G1 X20 Y0 Z1 E6",
                "; Homing extrusion length after 6 mm (10 mm limit)",
                "G92 E0.0000",
                "G1 X40 Y0 Z1 E12",
            ],
            Body(bot, RobotType.ZMORPH));
    }

    [Fact]
    public void Compile_MarlinExtrusion_AccumulatesAbsoluteE()
    {
        Robot bot = ExtrudeTenTenTwenty(RobotType.MARLIN);
        bot.Extrude(false);
        bot.Move(0, 3, 4);
        bot.Extrude();
        bot.ExtrusionRateTo(0.03333);
        bot.Move(0, 0, 1);

        Assert.Equal(
            [
                "G0 X0 Y0 Z1 F1200",
                "G1 X10 Y0 Z1 E6",
                "G1 X20 Y0 Z1 E12",
                "G1 X40 Y0 Z1 E24",
                "G0 X40 Y3 Z5",
                "G1 X40 Y3 Z6 E24.03333",
            ],
            Body(bot, RobotType.MARLIN));
    }

    [Fact]
    public void Compile_InitializeAfterExtruding_StartsEAgainFromZero()
    {
        var bot = Extruding(RobotType.MARLIN, 0, 0, 1, 0.1);
        bot.Move(10, 0, 0);
        bot.Initialize();
        bot.Move(10, 0, 0);

        string[] body = Body(bot, RobotType.MARLIN);

        Assert.Equal(["G0 X0 Y0 Z1 F1200", "G1 X10 Y0 Z1 E1", "G0 Z11 F300", "G28", "G92 E0", "G1 X20 Y0 Z1 E1 F1200"], body);
    }

    [Fact]
    public void Compile_MarlinHorizontalArc_WritesG2WithCentreOffsetAndArcLengthExtrusion()
    {
        var bot = Extruding(RobotType.MARLIN, 0, 0, 5, 0.1);
        // From (0,0) over (10,10) to (20,0): clockwise seen from above, centre (10,0), half a circle of radius 10.
        bot.ArcMotionTo(10, 10, 5, 20, 0, 5);
        bot.ArcMotionTo(30, -10, 5, 40, 0, 5);

        string[] body = Body(bot, RobotType.MARLIN);

        Assert.Equal("G2 X20 Y0 Z5 I10 J0 E3.14159", body[1]);
        Assert.Equal("G3 X40 Y0 Z5 I10 J0 E6.28319", body[2]);
    }

    [Fact]
    public void Compile_ZMorphArc_StraightSegmentsOnTheCircleWithProportionalE()
    {
        var bot = Extruding(RobotType.ZMORPH, 0, 0, 5, 0.1);
        bot.ArcMotionTo(10, 10, 5, 20, 0, 5);

        string[] segments = Body(bot, RobotType.ZMORPH).Skip(2).ToArray();

        // Chords within 0.01 mm of a radius-10 arc: 2·acos(1 − 0.001) ≈ 0.0894 rad each, so 36 segments for half a turn.
        Assert.Equal(36, segments.Length);
        Assert.Equal("G1 X20 Y0 Z5 E3.14159", segments[^1]);
        double previousE = 0;
        foreach (string line in segments)
        {
            string[] words = line.Split(' ');
            double x = double.Parse(words[1][1..], CultureInfo.InvariantCulture);
            double y = double.Parse(words[2][1..], CultureInfo.InvariantCulture);
            double e = double.Parse(words[4][1..], CultureInfo.InvariantCulture);
            Assert.Equal(10, Math.Sqrt((x - 10) * (x - 10) + y * y), 2);
            Assert.True(y >= 0, line);
            Assert.Equal(Math.PI / 36, e - previousE, 4);
            previousE = e;
        }
    }

    [Fact]
    public void Compile_MarlinVerticalArc_StraightSegments()
    {
        var bot = NewBot(RobotType.MARLIN);
        bot.MoveTo(0, 0, 0);
        bot.ArcMotionTo(10, 0, 10, 20, 0, 0);

        string[] body = Body(bot, RobotType.MARLIN);

        Assert.True(body.Length > 10);
        Assert.All(body.Skip(1), l => Assert.StartsWith("G0 X", l, StringComparison.Ordinal));
        Assert.Equal("G0 X20 Y0 Z0", body[^1]);
    }

    [Fact]
    public void Compile_TheFastestSpeedAllowed_IsWrittenInMmPerMinuteWithoutExponent()
    {
        // 1E+308 mm/s used to reach the writer (as "FInfinity", then as the largest double); the state now refuses speeds
        // beyond 1,000,000 mm/s, so the fastest feed a program can hold is 60,000,000 mm/min.
        foreach (RobotType brand in new[] { RobotType.ZMORPH, RobotType.MARLIN })
        {
            var bot = NewBot(brand);
            Assert.Throws<ActionRefusedException>(() => bot.SpeedTo(1e308));
            bot.SpeedTo(1e6);
            bot.MoveTo(0, 0, 10);

            string[] body = Body(bot, brand);

            string[] expected = brand == RobotType.ZMORPH
                ? ["G1 F60000000", "G1 X0 Y0 Z10"]
                : ["G0 X0 Y0 Z10 F60000000"];
            Assert.Equal(expected, body);
        }
    }

    [Fact]
    public void Compile_PopSettings_FeedRateSentAgain()
    {
        foreach (RobotType brand in new[] { RobotType.ZMORPH, RobotType.MARLIN })
        {
            var bot = NewBot(brand);
            bot.SpeedTo(10);
            bot.MoveTo(0, 0, 10);
            bot.PushSettings();
            bot.SpeedTo(50);
            bot.Move(10, 0, 0);
            bot.PopSettings();
            bot.Move(10, 0, 0);

            string[] body = Body(bot, brand);

            string[] expected = brand == RobotType.ZMORPH
                ? ["G1 F600", "G1 X0 Y0 Z10", "G1 F3000", "G1 X10 Y0 Z10", "G1 F600", "G1 X20 Y0 Z10"]
                : ["G0 X0 Y0 Z10 F600", "G0 X10 Y0 Z10 F3000", "G0 X20 Y0 Z10 F600"];
            Assert.Equal(expected, body);
        }
    }

    [Fact]
    public void Compile_TemperaturesWaitsAndOutputs_NativeLines()
    {
        var bot = NewBot(RobotType.MARLIN);
        bot.TemperatureTo(205.4, "extruder", false);
        bot.TemperatureTo(215, "extruder", true);
        bot.TemperatureTo(55, "bed", false);
        bot.Temperature(5, "bed", true);
        bot.TemperatureTo(40, "chamber", false);
        bot.TemperatureTo(45, "chamber", true);
        bot.Wait(250);
        bot.WriteDigital(7, true);
        bot.WriteDigital(7, false);
        bot.WriteAnalog(9, 128);

        Assert.Equal(
            ["M104 S205", "M109 S215", "M140 S55", "M190 S60", "M141 S40", "M191 S45", "G4 P250", "M42 P7 S255", "M42 P7 S0", "M42 P9 S128"],
            Body(bot, RobotType.MARLIN));
    }

    [Fact]
    public void Compile_StartAndEndSequences_OnlyFromInitializeAndTerminate()
    {
        var bot = NewBot(RobotType.ZMORPH);
        bot.SpeedTo(25);
        bot.Initialize();
        bot.Terminate();

        string[] body = Body(bot, RobotType.ZMORPH);

        Assert.Equal(
            [
                "G1 F1500",
                "G91", "G1 Z1.000 F200.000", "G90", "G28 X0.000 Y0.00", "G1 X117.500 Y125.000 F8000.000", "G28 Z0.000", "G92 E0.00000", "M82",
                "G1 F1500",
                "G92 E0.0000", "G91", "G1 E-3.00000 F1800.000", "G90", "G92 E0.00000", "G1 Z30.581 F300", "G1 X117.5 Y220",
                "T0", "M104 S0", "T1", "M104 S0", "M140 S0", "M106 S0", "M84", "M220 S100",
            ],
            body);
        Assert.Equal(["G28", "G92 E0", "M104 S0", "M140 S0", "M107", "M84"], Body(ReInitialized(RobotType.MARLIN), RobotType.MARLIN));
    }

    /// <summary>A 100 mm tall print: the ending must rise above it before travelling, never go diagonally down through it.</summary>
    [Theory]
    [InlineData(RobotType.ZMORPH)]
    [InlineData(RobotType.MARLIN)]
    public void Compile_TerminateAfterATallPrint_RisesAboveThePrintBeforeTravelling(RobotType brand)
    {
        var bot = Extruding(brand, 50, 50, 0.3, 0.05);
        bot.MoveTo(50, 50, 100);
        bot.MoveTo(60, 50, 100);
        bot.Extrude(false);
        bot.MoveTo(60, 50, 40);
        bot.Terminate();

        string[] body = Body(bot, brand);
        string[] ending = body.SkipWhile(l => !l.StartsWith(brand == RobotType.ZMORPH ? "G92 E0.0000" : "G0 X60 Y50 Z40")).Skip(1).ToArray();

        Assert.Equal(
            brand == RobotType.ZMORPH
                ? ["G91", "G1 E-3.00000 F1800.000", "G90", "G92 E0.00000", "G1 Z110 F300", "G1 X117.5 Y220", "T0", "M104 S0", "T1", "M104 S0", "M140 S0", "M106 S0", "M84", "M220 S100"]
                : ["G0 Z110 F300", "M104 S0", "M140 S0", "M107", "M84"],
            ending);
    }

    [Theory]
    [InlineData(RobotType.ZMORPH, "G1 Z35.5 F300", "G91")]
    [InlineData(RobotType.MARLIN, "G0 Z35.5 F300", "G28")]
    public void Compile_InitializeAfterPrinting_RisesAboveThePrintBeforeHoming(RobotType brand, string rise, string homingStart)
    {
        var bot = NewBot(brand);
        bot.MoveTo(10, 10, 25.5);
        bot.MoveTo(10, 10, 5);
        bot.Initialize();

        string[] body = Body(bot, brand);
        int at = Array.IndexOf(body, rise);

        Assert.True(at > 0, string.Join("\n", body));
        Assert.Equal(homingStart, body[at + 1]);
    }

    private static Robot ReInitialized(RobotType brand)
    {
        var bot = NewBot(brand);
        bot.Initialize();
        bot.Terminate();
        return bot;
    }

    [Fact]
    public void Compile_ActionsAPrinterCannotDo_CommentAndWarningEach()
    {
        var bot = NewBot(RobotType.MARLIN);
        bot.MoveTo(0, 0, 10);
        bot.Rotate(0, 0, 1, 30);
        bot.PrecisionTo(2);
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.TransformTo(0, 0, 20, 0, 1, 0, 1, 0, 0);
        bot.WriteDigital("DO_1", true);
        bot.WriteAnalog(1, 300);
        bot.ExternalAxisTo(1, 10);
        bot.AccelerationTo(0);

        RobotProgram program = Compile(bot, RobotType.MARLIN);
        string[] body = Body(bot, RobotType.MARLIN);

        Assert.Equal(
            [
                "G0 X0 Y0 Z10 F1200",
                "; ACTION \"Rotate 30 deg around [0, 0, 1]\" NOT APPLICABLE TO THIS DEVICE",
                "; ACTION \"Set precision radius to 2 mm\" NOT APPLICABLE TO THIS DEVICE",
                "; ACTION \"Set joint rotations to [0, 0, 0, 0, 90, 0] deg\" NOT APPLICABLE TO THIS DEVICE",
                "G0 X0 Y0 Z20",
                "; ERROR on \"Turn digital IO \"DO_1\" ON\": G-code addresses outputs by pin number, and \"DO_1\" is not a number.",
                "; ERROR on \"Set analog IO 1 to 300\": printer outputs take values from 0 to 255, and 300 is outside that range.",
                "; ACTION \"Set external axis #1 to 10\" NOT APPLICABLE TO THIS DEVICE",
                "; ERROR on \"Set motion acceleration to 0 mm/s^2 or deg/s^2\": acceleration 0 means the device's default, which G-code cannot restore; the printer keeps its current acceleration.",
            ],
            body);
        Assert.Equal([2, 3, 4, 6, 7, 8, 9], program.Warnings.Select(w => w.ActionId));
    }

    [Fact]
    public void Compile_TransformWithNewOrientation_MovesAndWarns()
    {
        var bot = NewBot(RobotType.ZMORPH);
        bot.MoveTo(0, 0, 10);
        bot.TransformTo(5, 0, 10, 0, 1, 0, 1, 0, 0);

        RobotProgram program = Compile(bot, RobotType.ZMORPH);

        Assert.Equal(
            ["G1 F1200", "G1 X0 Y0 Z10", "; WARNING: a 3D printer cannot turn its tool; the change of orientation is ignored.", "G1 X5 Y0 Z10"],
            Body(bot, RobotType.ZMORPH));
        Assert.Single(program.Warnings);
    }

    [Fact]
    public void Compile_TurnsInARow_OneWarningAboveAndOneAfterTheRun()
    {
        var bot = NewBot(RobotType.ZMORPH);
        bot.MoveTo(0, 0, 10);
        bot.TransformTo(5, 0, 10, 0, 1, 0, 1, 0, 0);
        bot.TransformTo(6, 0, 10, 1, 0, 0, 0, 1, 0);
        bot.TransformTo(7, 0, 10, 0, 1, 0, 1, 0, 0);
        bot.MoveTo(8, 0, 10);

        RobotProgram program = Compile(bot, RobotType.ZMORPH);
        var file = program.Files[0].Lines.ToList();
        int first = file.IndexOf("G1 X5 Y0 Z10") + 1;

        Assert.Equal(
            ["G1 F1200", "G1 X0 Y0 Z10", "; WARNING: a 3D printer cannot turn its tool; the change of orientation is ignored.", "G1 X5 Y0 Z10",
             "G1 X6 Y0 Z10", "G1 X7 Y0 Z10", $"; WARNING: the same warning for 3 motions in a row, lines {first} to {first + 2} (written once, above the first)",
             "G1 X8 Y0 Z10"],
            Body(bot, RobotType.ZMORPH));
        Assert.Equal(3, program.Warnings.Count); // the program's warnings keep one per motion
    }

    [Fact]
    public void Compile_UserText_CannotBreakOutOfMessagesOrComments()
    {
        foreach (RobotType brand in new[] { RobotType.ZMORPH, RobotType.MARLIN })
        {
            var bot = NewBot(brand);
            bot.Message("Hot;\nG28 (careful)");
            bot.Comment("x\r\nM84");

            string[] body = Body(bot, brand, human: true);

            string message = brand == RobotType.ZMORPH ? "M70 P1000 (Hot, G28 [careful])" : "M117 Hot, G28 [careful]";
            Assert.Equal([message + "  ; [Display message \"Hot; G28 (careful)\"]", "; x  M84"], body);
        }
    }

    [Fact]
    public void Compile_HumanComments_OnCodeLinesAndAloneForNoCodeActions()
    {
        var bot = NewBot(RobotType.MARLIN);
        bot.SpeedTo(40);
        bot.MoveTo(1, 2, 3);

        Assert.Equal(
            ["; [Set motion speed to 40 mm/s or deg/s]", "G0 X1 Y2 Z3 F2400  ; [Move to [1, 2, 3] mm]"],
            Body(bot, RobotType.MARLIN, human: true));
    }

    [Theory]
    [InlineData(RobotType.ZMORPH)]
    [InlineData(RobotType.MARLIN)]
    public void Compile_TwiceAndUnderGermanCulture_SameText(RobotType brand)
    {
        Robot bot = ReferencePrograms.Issue("Print3D", brand);
        IReadOnlyList<string> first = Compile(bot, brand, human: true).Files[0].Lines;
        CultureInfo saved = CultureInfo.CurrentCulture;
        try
        {
            CultureInfo.CurrentCulture = new CultureInfo("de-DE");
            Assert.Equal(first, Compile(bot, brand, human: true).Files[0].Lines);
        }
        finally
        {
            CultureInfo.CurrentCulture = saved;
        }
        Assert.Equal(first, Compile(bot, brand, human: true).Files[0].Lines);
        Assert.Contains(first, l => l.StartsWith("G1 X50 Y50 Z0.5 E4.01", StringComparison.Ordinal));
    }

    [Theory]
    [MemberData(nameof(KrlGoldenTests.ReferenceProgramNames), MemberType = typeof(KrlGoldenTests))]
    public void Compile_ReferencePrograms_NoTrailingSpacesAndAsciiOnly(string name)
    {
        foreach (RobotType brand in new[] { RobotType.ZMORPH, RobotType.MARLIN })
        {
            foreach (bool human in new[] { true, false })
            {
                var lines = Compile(ReferencePrograms.Issue(name, brand), brand, human).Files[0].Lines;
                Assert.All(lines, l => Assert.False(l.EndsWith(' '), $"trailing space in \"{l}\""));
                Assert.All(lines, l => Assert.True(l.All(char.IsAscii), l));
            }
        }
    }
}

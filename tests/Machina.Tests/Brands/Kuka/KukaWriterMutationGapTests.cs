namespace Machina.Tests.Brands.Kuka;

/// <summary>
/// Behaviour of the KRL writer that the other KUKA tests left unchecked (found by mutation testing, tests/mutation/run.sh kuka):
/// every reserved word, the edges of names and numbers, and the lines each action writes.
/// </summary>
public class KukaWriterMutationGapTests
{
    // The KRL reserved words the writer refuses, written out again here on purpose: a word lost from the writer's table would let
    // a module or signal named after it through, and the program would not compile on the controller.
    private static readonly string[] ReservedWords =
    [
        "AND", "ANIN", "ANOUT", "AXIS", "B_AND", "B_EXOR", "B_NOT", "B_OR", "BOOL", "BRAKE", "C_DIS", "C_ORI", "C_PTP", "C_VEL",
        "CA", "CASE", "CHAR", "CIRC", "CIRC_REL", "CONST", "CONST_VEL", "CONTINUE", "DECL", "DEF", "DEFAULT", "DEFDAT", "DEFFCT",
        "DELAY", "DISTANCE", "DO", "E6AXIS", "E6POS", "ELSE", "END", "ENDDAT", "ENDFCT", "ENDFOR", "ENDIF", "ENDLOOP", "ENDSPLINE",
        "ENDSWITCH", "ENDWHILE", "ENUM", "EXIT", "EXOR", "EXT", "EXTFCT", "FALSE", "FOR", "FRAME", "GLOBAL", "GOTO", "HALT", "IF",
        "IMPORT", "INT", "INTERRUPT", "IS", "LIN", "LIN_REL", "LOOP", "MAXIMUM", "MINIMUM", "NOT", "OR", "POS", "PRIO", "PTP",
        "PTP_REL", "PUBLIC", "REAL", "REPEAT", "RESUME", "RETURN", "SCIRC", "SEC", "SIGNAL", "SLIN", "SPLINE", "SPTP", "STEP",
        "STRUC", "SWITCH", "THEN", "TIME_BLOCK", "TO", "TRIGGER", "TRUE", "UNTIL", "WAIT", "WHEN", "WHILE",
    ];

    [Fact]
    public void IsValidName_EveryReservedWordInAnyCase_IsRefused()
    {
        string[] accepted = ReservedWords
            .SelectMany(w => new[] { w, w.ToLowerInvariant() })
            .Where(KrlText.IsValidName)
            .ToArray();

        Assert.Empty(accepted);
    }

    [Fact]
    public void ModuleName_EveryReservedWord_IsPrefixed()
    {
        string[] unprefixed = ReservedWords.Where(w => KrlText.ModuleName(w) != "M_" + w).ToArray();

        Assert.Empty(unprefixed);
    }

    [Fact]
    public void Compile_ReservedWordAsSignalName_IsAnErrorNotAnAssignment()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.WriteDigital("wait", true);

        string line = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false }).Files[0].Lines[^3];

        Assert.Equal("  ; ERROR on \"Turn digital IO \"wait\" ON\": \"wait\" is neither an output number nor a valid KRL signal name "
            + "(letters, digits and '_', at most 24 characters).", line);
    }

    [Theory]
    [InlineData("A23456789012345678901234", true)]    // 24 characters: the longest name
    [InlineData("A234567890123456789012345", false)]  // 25
    [InlineData("", false)]
    [InlineData("1st", false)]
    [InlineData("_first1", true)]
    [InlineData("a.b", false)]
    [InlineData("Linear", true)]                      // starts like a keyword but is not one
    public void IsValidName_LengthFirstCharacterAndLetters_AsKrlAllows(string name, bool expected) =>
        Assert.Equal(expected, KrlText.IsValidName(name));

    [Theory]
    [InlineData("target7", "M_target7")]                                  // the writer declares target1, target2, ...
    [InlineData("MACHINA_ACC_CP", "M_MACHINA_ACC_CP")]                    // the acceleration variable, any case
    [InlineData("bas", "M_bas")]                                          // system routines the INI fold calls
    [InlineData("Ir_StopM", "M_Ir_StopM")]
    [InlineData("3D print", "M_3D_print")]                                // digit first, space replaced
    [InlineData("target123456789012345678", "M_target1234567890123456")]  // prefixed, then cut to 24
    [InlineData("ABCDEFGHIJKLMNOPQRSTUVWX", "ABCDEFGHIJKLMNOPQRSTUVWX")]  // 24 characters, kept whole
    [InlineData("targets", "targets")]                                    // not target + digits
    public void ModuleName_GeneratedSystemAndOddNames_AreMadeSafe(string programName, string expected) =>
        Assert.Equal(expected, KrlText.ModuleName(programName));

    [Fact]
    public void Compile_ProgramNameThatIsAKeyword_BothFilesExplainTheModuleName()
    {
        var bot = Robot.Create("Circ", RobotType.KUKA);
        bot.MoveTo(100, 0, 300);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { InlineTargets = false });
        const string note = "; KRL module name \"M_Circ\": the program name \"Circ\" adapted to KRL's naming rules (24 characters, no keywords).";

        Assert.Equal(["&ACCESS RVP", "&REL 1", "DEFDAT M_Circ"], program.Files[1].Lines.Take(3));
        Assert.Equal(note, program.Files[0].Lines[8]);
        Assert.Equal(note, program.Files[1].Lines[6]);
        Assert.DoesNotContain(Robot.Create("Test", RobotType.KUKA).Compile(RobotType.KUKA).Files[0].Lines,
            l => l.StartsWith("; KRL module name", StringComparison.Ordinal));
    }

    [Fact]
    public void Compile_SpeedAndAccelerationThatWouldPrintAsZero_RaisedToTheSmallestWithAWarning()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.SpeedTo(0.0004);
        bot.AccelerationTo(0.0004);
        bot.SpeedTo(0.001);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });

        Assert.Equal(["  $VEL.CP = 0.000001", "  $ACC.CP = 0.000001", "  $VEL.CP = 0.000001", "", "END"], program.Files[0].Lines.TakeLast(5));
        Assert.Equal(
            [
                "KRL speeds are written in m/s with 6 decimals; 0.0004 mm/s would be 0 and was raised to 0.000001 m/s.",
                "KRL accelerations are written in m/s^2 with 6 decimals; 0.0004 mm/s^2 would be 0 and was raised to 0.000001 m/s^2.",
            ],
            program.Warnings.Select(w => w.Message));
        Assert.Equal([1, 2], program.Warnings.Select(w => w.ActionId));
    }

    [Theory]
    [InlineData(0.0004, true)]
    [InlineData(0.0005, true)]   // 0.0000005 m/s rounds (to even) to 0
    [InlineData(0.0015, false)]  // 0.0000015 m/s rounds to 0.000002
    [InlineData(0.001, false)]   // exactly the smallest rate
    [InlineData(0, false)]       // 0 is not raised: it means "controller default" for accelerations
    [InlineData(-1, false)]
    public void RoundsToZero_Rates_OnlyPositiveValuesBelowHalfAMicrometre(double perMm, bool expected) =>
        Assert.Equal(expected, KrlFormat.RoundsToZero(perMm));

    [Theory]
    [InlineData(-180, "180")]
    [InlineData(-179.9996, "180")]        // −180 to 3 decimals
    [InlineData(-179.9994, "-179.999")]
    [InlineData(180, "180")]
    [InlineData(-90, "-90")]
    public void Angle_MinusOneEighty_IsWrittenAsOneEighty(double degrees, string expected) =>
        Assert.Equal(expected, KrlFormat.Angle(degrees));

    [Fact]
    public void Degrees_JustAboveMinusOneEighty_IsKept() => Assert.Equal(-179.9994, KrlFormat.Degrees(-179.9994));

    private static IReadOnlyList<string> Lines(Robot bot, bool human = false) =>
        bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = human }).Files[0].Lines;

    /// <summary>The lines from <paramref name="first"/> on, <paramref name="count"/> of them.</summary>
    private static IEnumerable<string> From(IReadOnlyList<string> lines, string first, int count) =>
        lines.Skip(lines.ToList().IndexOf(first)).Take(count);

    [Fact]
    public void Compile_DeclarationsAndAccelerationVariable_OneBlockFollowedByAnEmptyLine()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.CustomCode("DECL INT counter", isDeclaration: true);
        bot.AccelerationTo(0);

        var lines = Lines(bot);

        Assert.Equal(["DEF Test( )"], lines.Where(l => l.StartsWith("DEF ", StringComparison.Ordinal)));
        Assert.Equal(["  DECL INT counter", "  DECL REAL machina_acc_cp", "", ";FOLD INI"], From(lines, "  DECL INT counter", 4));
        Assert.Equal(["  PTP $AXIS_ACT", "  machina_acc_cp = $ACC.CP", "  $BASE = $NULLFRAME"], From(lines, "  PTP $AXIS_ACT", 3));
    }

    [Fact]
    public void Compile_OnlyACustomDeclaration_EmptyLineBeforeTheIniFold()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.CustomCode("DECL INT counter", isDeclaration: true);

        var lines = Lines(bot, human: true);

        Assert.Equal(["  DECL INT counter", "", ";FOLD INI"], From(lines, "  DECL INT counter", 3));
        Assert.DoesNotContain(lines, l => l.Contains("machina_acc_cp", StringComparison.Ordinal));
        Assert.Equal(["  ; [Add custom declaration: \"DECL INT counter\"]", "", "END"], lines.TakeLast(3));
    }

    [Fact]
    public void Compile_NoDeclarations_TheIniFoldFollowsTheHeader()
    {
        var lines = Lines(Robot.Create("Test", RobotType.KUKA));

        Assert.Equal(["; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.", "", ";FOLD INI"],
            From(lines, "; run it at reduced speed, keep clear of the working area and keep the emergency stop in reach.", 3));
    }

    [Fact]
    public void Compile_SettingsChangedBeforeTheProgram_StartBlockWritesThem()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.SpeedTo(100);
        bot.AccelerationTo(500);
        bot.PrecisionTo(1);
        bot.ClearProgram();

        Assert.Equal(["  $ADVANCE = 3", "  $VEL.CP = 0.1", "  $ACC.CP = 0.5", "  $APO.CDIS = 1", ""], From(Lines(bot), "  $ADVANCE = 3", 5));
    }

    [Fact]
    public void Compile_DigitalOutputZero_IsAnError()
    {
        const int pin = 0;
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.WriteDigital(pin, true);

        Assert.Equal($"  ; ERROR on \"Turn digital IO {pin} ON\": $OUT outputs are numbered 1 to 4096, so output {pin} does not exist.",
            Lines(bot)[^3]);
    }

    [Fact]
    public void Compile_ActionsForOtherMachines_EachWarningSaysWhy()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.ArmAngleTo(30);
        bot.Initialize();
        bot.Extrude();
        bot.Message("hi");

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });

        Assert.Equal(
            [
                "KUKA arms of this kind have no arm angle to set.",
                "a KUKA program needs no start-up or shut-down sequence; this is for 3D printers.",
                "a KUKA arm has no extruder or heated parts; this is for 3D printers.",
                "KRL has no plain instruction to show a message; it is written as a comment.",
            ],
            program.Warnings.Select(w => w.Message));
        Assert.Equal("  ; ACTION \"Set arm-angle to 30 deg\" NOT APPLICABLE TO THIS DEVICE", program.Files[0].Lines[^6]);
    }

    [Fact]
    public void Compile_AttachTool_WarnsThatTheLoadIsNotSent()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.DefineTool("pen", 0, 0, 100, 1, 0, 0, 0, 1, 0, 0.5, 0, 0, 50);
        bot.AttachTool("pen");

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });

        Assert.Equal("the weight and centre of gravity of tool \"pen\" are not sent; set its load data on the controller.",
            Assert.Single(program.Warnings).Message);
    }

    [Fact]
    public void Compile_PopSettingsWithHumanComments_CodeForWhatChangedElseAComment()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.PushSettings();
        bot.SpeedTo(300);
        bot.PopSettings();
        bot.PushSettings();
        bot.AccelerationTo(800);
        bot.PopSettings();
        bot.PushSettings();
        bot.PopSettings();

        var lines = Lines(bot, human: true);
        string[] pops = lines.Where(l => l.Contains("[Pop settings", StringComparison.Ordinal)).ToArray();

        Assert.Equal(
            [
                "  $VEL.CP = 0.02  ; [Pop settings]",
                "  $ACC.CP = machina_acc_cp  ; [Pop settings]",
                "  ; [Pop settings]",
            ],
            pops);
    }

    [Fact]
    public void Compile_JointMotionToAPose_WarnsOnceAboutPtpSpeed()
    {
        var bot = Robot.Create("Test", RobotType.KUKA);
        bot.MotionMode(MotionType.Joint);
        bot.MoveTo(400, 0, 400);
        bot.MoveTo(400, 0, 300);

        RobotProgram program = bot.Compile(RobotType.KUKA, new CompileOptions { HumanComments = false });

        Assert.Equal(2, Assert.Single(program.Warnings).ActionId);
        Assert.Equal(
            [
                "  ; WARNING: joint (PTP) motions run at the controller's axis speeds ($VEL_AXIS, set by BAS #INITMOV); the Machina speed sets $VEL.CP for LIN and CIRC motions only.",
                "  PTP {E6POS: X 400, Y 0, Z 400, A 180, B 0, C 180} C_PTP",
                "  PTP {E6POS: X 400, Y 0, Z 300, A 180, B 0, C 180} C_PTP",
                "",
                "END",
            ],
            program.Files[0].Lines.TakeLast(5));
    }
}

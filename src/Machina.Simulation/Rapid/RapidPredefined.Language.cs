namespace Machina.Simulation.Rapid;

/// <summary>
/// The language's predefined constants that programs written for a controller use (Instructions, Functions and Data types
/// reference): WAIT_MAX, the operating and running modes (symnum), the integer types of raw bytes (inttypes), the comparison
/// operators (opnum), the character sets (STR_…), the message box's buttons and icons and the disks.
/// </summary>
internal static partial class RapidPredefined
{
    /// <summary>WAIT_MAX: "wait for ever" for a \Time or \MaxTime argument (seconds).</summary>
    public const double WaitMax = 8_388_608;

    private static readonly (string Name, string Type, double Value)[] LanguageNumbers =
    [
        ("WAIT_MAX", "num", WaitMax),
        ("OP_UNDEF", "symnum", 0), ("OP_AUTO", "symnum", 1), ("OP_MAN_PROG", "symnum", 2), ("OP_MAN_TEST", "symnum", 3),
        ("RUN_UNDEF", "symnum", 0), ("RUN_CONT_CYCLE", "symnum", 1), ("RUN_INSTR_FWD", "symnum", 2), ("RUN_INSTR_BWD", "symnum", 3),
        ("RUN_SIM", "symnum", 4), ("RUN_STEP_MOVE", "symnum", 5),
        ("USINT", "inttypes", 1), ("UINT", "inttypes", 2), ("UDINT", "inttypes", 4), ("ULINT", "inttypes", 8),
        ("SINT", "inttypes", -1), ("INT", "inttypes", -2), ("DINT", "inttypes", -4), ("LINT", "inttypes", -8),
        ("LT", "opnum", 1), ("LTEQ", "opnum", 2), ("EQ", "opnum", 3), ("NOTEQ", "opnum", 4), ("GTEQ", "opnum", 5), ("GT", "opnum", 6),
        ("BTN_NONE", "btnres", 0), ("BTN_OK", "btnres", 1), ("BTN_ABORT", "btnres", 2), ("BTN_RETRY", "btnres", 3), ("BTN_IGNORE", "btnres", 4),
        ("BTN_CANCEL", "btnres", 5), ("BTN_YES", "btnres", 6), ("BTN_NO", "btnres", 7),
        ("btnNone", "buttondata", -1), ("btnOK", "buttondata", 0), ("btnAbrtRtryIgn", "buttondata", 1), ("btnOKCancel", "buttondata", 2),
        ("btnRetryCancel", "buttondata", 3), ("btnYesNo", "buttondata", 4), ("btnYesNoCancel", "buttondata", 5),
        ("iconNone", "icondata", 0), ("iconInfo", "icondata", 1), ("iconWarning", "icondata", 2), ("iconError", "icondata", 3), ("iconQuestion", "icondata", 4),
        ("EOF_BIN", "num", -1), ("EOF_NUM", "num", 9.998E36),
    ];

    private static readonly (string Name, string Value)[] LanguageStrings =
    [
        ("STR_DIGIT", "0123456789"), ("STR_UPPER", "ABCDEFGHIJKLMNOPQRSTUVWXYZ"), ("STR_LOWER", "abcdefghijklmnopqrstuvwxyz"), ("STR_WHITE", " "),
        ("ERRSTR_EMPTY", ""), ("stEmpty", ""), ("ERRSTR_UNUSED", ""), ("diskhome", "HOME:"), ("disktemp", "TEMP:"), ("diskram", "RAMDISK:"), ("EOF", "EOF"),
    ];

    private static void AddLanguageConstants(RapidProgram program)
    {
        foreach ((string name, string type, double value) in LanguageNumbers)
        {
            Add(program, name, RapidTypes.All[type], value);
        }
        foreach ((string name, string value) in LanguageStrings)
        {
            Add(program, name, RapidTypes.String, value);
        }
    }
}

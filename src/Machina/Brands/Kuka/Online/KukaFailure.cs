namespace Machina;

/// <summary>
/// The failure report of the KRL driver, <c>&lt;F ID="id" Code="code" Text="text"&gt;&lt;/F&gt;</c>: the action with that id could not
/// run, so the driver did not start it, sent this instead of its acknowledgement and halted (nothing after it runs). The codes
/// are the driver's own checks before an action (docs/protocol-kuka.md), and <see cref="Stopped"/>: the host stopped the action
/// under way (the driver then keeps serving the next connection).
/// </summary>
internal static class KukaFailure
{
    /// <summary>A Cartesian target with no axis solution within the software limit switches (KRL's INVERSE failed).</summary>
    public const int NotReachable = 1;

    /// <summary>An axis target beyond a software limit switch (<c>$SOFTN_END</c> / <c>$SOFTP_END</c>).</summary>
    public const int SoftwareLimit = 2;

    /// <summary>A speed (<c>$VEL.CP</c>) of 0 or less: the motions after it would never end.</summary>
    public const int NoSpeed = 3;

    /// <summary>An output number outside <c>$OUT[1..4096]</c> or <c>$ANOUT[1..32]</c>.</summary>
    public const int NoSuchOutput = 4;

    /// <summary>An analog value outside -1..1, the range of <c>$ANOUT</c>.</summary>
    public const int AnalogRange = 5;

    /// <summary>An input still not at its value when the wait's time limit passed (timer 15).</summary>
    public const int WaitTimedOut = 6;

    /// <summary>The action that ran when the host stopped the motion (Robot.Stop): it ended where the arm was, the rest was dropped.</summary>
    public const int Stopped = 7;

    /// <summary>The text the driver sends (and shows in its quit message) for a code.</summary>
    public static string Describe(int code) => code switch
    {
        NotReachable => "Target not reachable: no axis position within the software limit switches reaches it.",
        SoftwareLimit => "Software limit switch: an axis target is beyond its software limits.",
        NoSpeed => "The speed ($VEL.CP) is 0: the motion would never end.",
        NoSuchOutput => "Output does not exist: the number is outside the controller's outputs.",
        AnalogRange => "Analog value out of range: $ANOUT takes values from -1 to 1.",
        WaitTimedOut => "Input did not change within the time limit: the wait for $IN timed out.",
        Stopped => "Stopped by Machina (Robot.Stop): the motion stopped where the arm was.",
        _ => "The driver could not run the action and halted.",
    };

    /// <summary><c>&lt;F ID="id" Code="code" Text="text"&gt;&lt;/F&gt;</c>, as the driver writes it.</summary>
    public static string Message(int id, int code) =>
        "<F ID=\"" + Num.I(id) + "\" Code=\"" + Num.I(code) + "\" Text=\"" + Describe(code) + "\"></F>";
}

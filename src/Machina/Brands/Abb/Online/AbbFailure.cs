using System.Globalization;

namespace Machina;

/// <summary>
/// The failure report of the RAPID driver, <c>$26 id code;</c>: the request with that id could not run and the driver program
/// stopped (nothing after it runs). Codes of 10000 and more are the controller's event-log numbers; smaller ones are the
/// driver's own checks. Only numbers, so that the original Machina.NET host (which parses every <c>$</c> value as a number and
/// ignores codes it does not know) still reads the stream (docs/protocol-abb.md).
/// </summary>
internal static class AbbFailure
{
    /// <summary>Event 50050, "Position outside reach": a target outside the arm's working range or a joint beyond its limits.</summary>
    public const int OutsideReach = 50050;

    /// <summary>Event 50063, "Circle uncertain": a MoveC whose CirPoint and ToPoint are less than 1° apart seen from its start point.</summary>
    public const int CircleUncertain = 50063;

    /// <summary>The driver's own check: a move with a speed (v_tcp) of 0 or less would never end, so it is not started.</summary>
    public const int NoSpeed = 1;

    /// <summary>Any other RAPID error caught by the driver's error handler; its ERRNO follows in the text.</summary>
    public const int RapidError = 2;

    /// <summary>The driver's WaitDI reached its \MaxTime before the input did (RAPID error ERR_WAIT_MAXTIME).</summary>
    public const int WaitTimedOut = 3;

    /// <summary>The monitor task held the motion on the host's stop (Robot.Stop) and the driver failed the request under way; nothing after it runs.</summary>
    public const int StoppedByHost = 4;

    /// <summary>The reason for a failure code, in the controller's words (as its event log or the driver's pendant shows it).</summary>
    public static string Describe(int code) => code switch
    {
        OutsideReach => "Position outside reach (event 50050): the target is outside the robot's working range or a joint would pass its limits.",
        CircleUncertain => "Circle uncertain (event 50063): the arc's start point, through point and end are almost on one line (MoveC needs its through point and end at least 1° apart seen from the start).",
        NoSpeed => "The speed is 0: the move would never end, so the driver did not start it.",
        WaitTimedOut => "The input did not reach its value within the time limit (WaitDI \\MaxTime, RAPID error ERR_WAIT_MAXTIME); the driver program stopped.",
        StoppedByHost => "Stopped by the host (Robot.Stop): the motion stopped on its path and nothing after it ran.",
        RapidError => "A RAPID error stopped the driver program (see the controller's event log).",
        _ => $"The controller reported error {code.ToString(CultureInfo.InvariantCulture)} and stopped the driver program.",
    };

    /// <summary><c>$26 id code;</c>, as the driver writes it.</summary>
    public static string Message(int id, int code) =>
        "$26 " + id.ToString(CultureInfo.InvariantCulture) + " " + code.ToString(CultureInfo.InvariantCulture) + ";";
}

namespace Machina.Simulation.Rapid;

/// <summary>
/// Fixed-position checks and speed-following outputs (RAPID reference: TriggCheckIO, TriggSpeed), fired by TriggL, TriggJ and TriggC
/// as the other Trigg events are. TriggCheckIO compares a signal with a value where the TCP passes its point and, when the
/// comparison fails, orders its interrupt (with \StopMove the robot first stops on its path; the trap's StartMove lets it go on).
/// TriggSpeed sets an analog output to ScaleValue times the TCP speed in mm/s from its point on, following the speed along the
/// move's ramps down to 0 where the move stops, each value ScaleLag earlier (\DipLag and \ErrDO are taken and not used).
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> TriggChecks() =>
    [
        Instruction("TriggCheckIO", [P("TriggData", "triggdata", true), P("Distance", "num"), Sw("Start"), Sw("Time"), P("Signal", null), P("Relation", "opnum"),
            P("CheckValue", null), Sw("StopMove"), P("Interrupt", "intnum")], call =>
        {
            if (call.Value(4) is not RapidSignalRef { Signal: { } name } || call.Machine.Task.Controller.Signal(name) is not { } signal)
            {
                throw ArgumentError(call, "TriggCheckIO: the Signal must be a signal of the IO configuration");
            }
            int relation = (int)call.Num(5);
            if (relation is < 1 or > 6)
            {
                throw ArgumentError(call, $"TriggCheckIO: the relation {relation} is not LT, LTEQ, EQ, NOTEQ, GTEQ or GT");
            }
            var data = (RapidTriggData)call.Value(0);
            RapidTriggEvent e = Define(call, "TriggCheckIO", call.Has(3), 0, null, 0, (int)call.Num(8), null);
            data.Event = e with { Check = (name, signal.Bank, signal.Index, relation, Convert.ToDouble(call.Value(6), System.Globalization.CultureInfo.InvariantCulture), call.Has(7)) };
        }),
        Instruction("TriggSpeed", [P("TriggData", "triggdata", true), P("Distance", "num"), Sw("Start"), P("ScaleLag", "num"), P("AOp", "signalao"),
            P("ScaleValue", "num"), Opt("DipLag", "num"), Opt("ErrDO", "signaldo"), Opt("Inhib", "bool", true)], call =>
        {
            double lag = call.Num(3);
            if (lag < 0)
            {
                throw ArgumentError(call, "TriggSpeed: the ScaleLag must not be negative");
            }
            (string name, int index) = Signal(call, 4, "ao");
            RapidCall at = call;
            Func<bool>? inhibit = call.Has(8) ? () => (bool)at.Value(8) : null;
            var data = (RapidTriggData)call.Value(0);
            RapidTriggEvent e = Define(call, "TriggSpeed", false, -lag, (name, "ao", index), call.Num(5), 0, inhibit);
            data.Event = e with { FollowsSpeed = true };
        }),
    ];

    /// <summary>True when a TriggCheckIO's signal stands in its relation to its value now.</summary>
    private static bool Holds(RapidTwinController c, (string Name, string Bank, int Index, int Relation, double Value, bool StopMove) check)
    {
        double now = check.Bank[0] is 'd' ? (c.Io.GetBit(check.Bank, check.Index) ? 1 : 0) : c.Io.GetNumber(check.Bank, check.Index);
        return check.Relation switch
        {
            1 => now < check.Value,
            2 => now <= check.Value,
            3 => now == check.Value,
            4 => now != check.Value,
            5 => now >= check.Value,
            _ => now > check.Value,
        };
    }
}

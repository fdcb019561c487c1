namespace Machina.Simulation.Rapid;

/// <summary>
/// Timer and signal interrupts (RAPID reference: ITimer, ISignalDI, ISignalDO, ISleep, IWatch, IDisable, IEnable). A trap runs between
/// two statements of its task, or while the task waits (WaitTime, WaitUntil, WaitDI).
/// </summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Events() =>
    [
        Instruction("ITimer", [Sw("Single"), Sw("SingleSafe"), P("Time", "num"), P("Interrupt", "intnum")], call =>
        {
            bool single = call.Has(0) || call.Has(1);
            double seconds = call.Num(2);
            double least = single ? 0.01 : 0.1;
            if (!(seconds >= least))
            {
                throw ArgumentError(call, $"ITimer: the time {RapidValues.FormatNumber(seconds)} s is below {RapidValues.FormatNumber(least)} s" +
                    (single ? "" : " (the least for a cyclic timer)"));
            }
            Ordered(call, "ITimer", call.Machine.Task.OrderTimer((int)call.Num(3), seconds, single));
        }),
        SignalOrder("ISignalDI", "di"),
        SignalOrder("ISignalDO", "do"),
        Instruction("ISleep", [P("Interrupt", "intnum")], call => Ordered(call, "ISleep", call.Machine.Task.Sleep((int)call.Num(0), asleep: true))),
        Instruction("IWatch", [P("Interrupt", "intnum")], call => Ordered(call, "IWatch", call.Machine.Task.Sleep((int)call.Num(0), asleep: false))),
        Instruction("IDisable", [], call => call.Machine.Task.Disable(true)),
        Instruction("IEnable", [], call => call.Machine.Task.Disable(false)),
    ];

    /// <summary>ISignalDI or ISignalDO on a signal of <paramref name="bank"/>: trigger value 0 (to low), 1 (to high) or 2 (each change).</summary>
    private static RapidBuiltin SignalOrder(string name, string bank) =>
        Instruction(name, [Sw("Single"), Sw("SingleSafe"), P("Signal", "signal" + bank), P("TriggValue", "dionum"), P("Interrupt", "intnum")], call =>
        {
            (_, int index) = Signal(call, 2, bank);
            double trigger = call.Num(3);
            if (trigger is not (0 or 1 or 2))
            {
                throw ArgumentError(call, $"{name}: the trigger value {RapidValues.FormatNumber(trigger)} is not 0, 1 or 2 (edge)");
            }
            Ordered(call, name, call.Machine.Task.OrderSignal((int)call.Num(4), bank, index, (int)trigger, call.Has(0) || call.Has(1)));
        });

    private static void Ordered(RapidCall call, string name, bool connected)
    {
        if (!connected)
        {
            throw ArgumentError(call, $"{name}: the interrupt is not connected to a trap (CONNECT it first)");
        }
    }
}

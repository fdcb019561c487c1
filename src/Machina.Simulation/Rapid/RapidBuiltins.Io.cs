using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>IO instructions and functions on the signals of the controller's IO configuration.</summary>
internal static partial class RapidBuiltins
{
    private static IEnumerable<RapidBuiltin> Io() =>
    [
        Instruction("SetDO", [Opt("SDelay", "num"), Sw("Sync"), P("Signal", "signaldo"), P("Value", "num")], call =>
        {
            double value = call.Num(3);
            if (value is not (0 or 1))
            {
                throw ArgumentError(call, $"SetDO: the value {RapidValues.FormatNumber(value)} is not 0 or 1");
            }
            (string name, int index) = Signal(call, 2, "do");
            RapidTwinController c = call.Machine.Task.Controller;
            c.SetBit("do", index, value == 1);
            c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} = {RapidValues.FormatNumber(value)}");
        }),
        Instruction("SetAO", [P("Signal", "signalao"), P("Value", "num")], call =>
        {
            double value = call.Num(1);
            (string name, int index) = Signal(call, 0, "ao");
            RapidTwinController c = call.Machine.Task.Controller;
            c.SetNumber("ao", index, value);
            c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} = {RapidValues.FormatNumber(value)}");
        }),
        Instruction("WaitDI", [P("Signal", "signaldi"), P("Value", "num"), Opt("MaxTime", "num"), Opt("TimeFlag", "bool", true)], call =>
        {
            (_, int index) = Signal(call, 0, "di");
            bool wanted = call.Num(1) == 1;
            RapidTwinController c = call.Machine.Task.Controller;
            if (call.Machine.Task.IsMotionTask)
            {
                c.Arm.FinishBlend(call.Machine.Task.CancellationToken); // a wait: the arm stops at its last waypoint first
            }
            double start = c.Clock.Seconds;
            double? max = call.Has(2) ? call.Num(2) : null;
            if (max is null && !c.Clock.RealTime && c.Io.GetBit("di", index) != wanted)
            {
                throw ArgumentError(call, "WaitDI would wait forever: nothing changes the twin's inputs while it runs without real time");
            }
            while (c.Io.GetBit("di", index) != wanted)
            {
                if (max is { } limit && c.Clock.Seconds - start >= limit)
                {
                    if (call.Has(3))
                    {
                        call.Set(3, true);
                        return;
                    }
                    throw call.Error(RapidErrorNumbers.WaitMaxTime, "WaitDI: the input did not change within \\MaxTime");
                }
                c.Clock.Wait(0.01, call.Machine.Task.CancellationToken);
                call.Machine.Task.RunPendingTraps();
            }
            if (call.Has(3))
            {
                call.Set(3, false);
            }
        }),
        Instruction("AliasIO", [P("FromSignal", null), P("ToSignal", "signaldo", true)], call =>
        {
            object from = call.Value(0);
            string? name = from as string ?? (from as RapidSignalRef)?.Signal;
            if (name is null || call.Machine.Task.Controller.Signal(name) is null)
            {
                throw call.Error(RapidErrorNumbers.AliasIoDef, $"AliasIO: the IO configuration has no signal \"{name}\"");
            }
            ((RapidSignalRef)call.Value(1)).Signal = name;
        }),
        Instruction("SetGO", [Opt("SDelay", "num"), P("Signal", "signalgo"), P("Value", "num")], call =>
        {
            double value = call.Num(2);
            if (value < 0 || value != Math.Floor(value))
            {
                throw ArgumentError(call, $"SetGO: the value {RapidValues.FormatNumber(value)} is not a whole number of 0 or more");
            }
            (string name, int index) = Signal(call, 1, "go");
            RapidTwinController c = call.Machine.Task.Controller;
            c.SetNumber("go", index, value);
            c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} = {RapidValues.FormatNumber(value)}");
        }),
        Instruction("PulseDO", [Sw("High"), Opt("PLength", "num"), P("Signal", "signaldo")], call =>
        {
            // The pulse (0.2 s unless \PLength) is not waited for: the output is left as the pulse ends it (low, or high with \High).
            (string name, int index) = Signal(call, 2, "do");
            RapidTwinController c = call.Machine.Task.Controller;
            c.SetBit("do", index, true);
            c.SetBit("do", index, call.Has(0));
            c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} pulsed");
        }),
        Function("GOutput", "num", [P("Signal", "signalgo")], call => call.Machine.Task.Controller.Io.GetNumber("go", Signal(call, 0, "go").Index)),
        Function("GInput", "num", [P("Signal", "signalgi")], call => call.Machine.Task.Controller.Io.GetNumber("gi", Signal(call, 0, "gi").Index)),
        Function("GOutputDnum", "dnum", [P("Signal", "signalgo")], call => call.Machine.Task.Controller.Io.GetNumber("go", Signal(call, 0, "go").Index)),
        Function("GInputDnum", "dnum", [P("Signal", "signalgi")], call => call.Machine.Task.Controller.Io.GetNumber("gi", Signal(call, 0, "gi").Index)),
        Function("DOutput", "num", [P("Signal", "signaldo")], call => Bit(call, "do")),
        Function("DInput", "num", [P("Signal", "signaldi")], call => Bit(call, "di")),
        Function("AOutput", "num", [P("Signal", "signalao")], call => call.Machine.Task.Controller.Io.GetNumber("ao", Signal(call, 0, "ao").Index)),
        Function("AInput", "num", [P("Signal", "signalai")], call => call.Machine.Task.Controller.Io.GetNumber("ai", Signal(call, 0, "ai").Index)),
    ];

    private static object Bit(RapidCall call, string bank) => call.Machine.Task.Controller.Io.GetBit(bank, Signal(call, 0, bank).Index) ? 1.0 : 0.0;

    /// <summary>The name and index of the signal a signal argument refers to, which must be of <paramref name="bank"/>.</summary>
    private static (string Name, int Index) Signal(RapidCall call, int p, string bank)
    {
        var signal = (RapidSignalRef)call.Value(p);
        if (signal.Signal is not { } name)
        {
            throw call.Error(RapidErrorNumbers.NoAliasIoDef, "the signal variable refers to no signal (AliasIO was not run)");
        }
        (string Bank, int Index)? found = call.Machine.Task.Controller.Signal(name);
        if (found is not { } s || s.Bank != bank)
        {
            throw call.Error(RapidErrorNumbers.AliasIoDef, $"the signal \"{name}\" is not a {bank.ToUpperInvariant()} signal of the IO configuration");
        }
        return (name, s.Index);
    }
}

using System.Globalization;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rapid;

/// <summary>
/// Data by name (GetDataVal, SetDataVal), semaphores (TestAndSet, WaitTestAndSet), waiting on a condition (WaitUntil), the
/// controller's modes (OpMode, RunMode), arithmetic instructions (Incr, Decr, Add, Clear), Set and Reset, Offs, Dim, CDate, CTime.
/// </summary>
internal static partial class RapidBuiltins
{
    /// <summary>How often WaitUntil looks at its condition when the program gives no \PollRate (seconds, as the manual's default).</summary>
    private const double DefaultPollSeconds = 0.1;

    private static IEnumerable<RapidBuiltin> DataAndWaits() =>
    [
        Instruction("GetDataVal", [P("Object", "string"), Opt("Block", "string"), Opt("TaskRef", "taskid"), Opt("TaskName", "string"),
            P("Value", null, true), Sw("Hidden")], call =>
        {
            RapidCell cell = DataNamed(call, 4);
            // \TaskName's task may be writing the record in place on its thread: a copy of one state of it (RapidCell.Read).
            object value = cell.Read(RapidValues.Copy)
                ?? throw call.Error(RapidErrorNumbers.SymAccess, $"GetDataVal: '{call.Str(0)}' was written during each attempt to read it");
            call.Set(4, value);
        }),
        Instruction("SetDataVal", [P("Object", "string"), Opt("Block", "string"), Opt("TaskRef", "taskid"), Opt("TaskName", "string"),
            P("Value", null), Sw("Hidden")], call =>
        {
            RapidCell cell = DataNamed(call, 4);
            if (cell.Storage == RapidStorage.Const)
            {
                throw call.Error(RapidErrorNumbers.SymAccess, $"SetDataVal: '{call.Str(0)}' is a constant");
            }
            cell.Value = RapidValues.Copy(call.Value(4));
            if (cell.Storage == RapidStorage.Pers)
            {
                call.Machine.Task.Controller.PersistentWritten();
            }
        }),
        Function("TestAndSet", "bool", [P("Object", "bool", true)], call =>
        {
            lock (call.Machine.Task.Controller.SemaphoreGate)
            {
                if ((bool)call.Value(0))
                {
                    return false;
                }
                call.Set(0, true);
                return true;
            }
        }),
        Instruction("WaitTestAndSet", [P("Object", "bool", true)], call =>
        {
            while (true)
            {
                lock (call.Machine.Task.Controller.SemaphoreGate)
                {
                    if (!(bool)call.Value(0))
                    {
                        call.Set(0, true);
                        return;
                    }
                }
                Poll(call, DefaultPollSeconds);
            }
        }),
        Instruction("WaitUntil", [Sw("InPos"), P("Cond", "bool"), Opt("MaxTime", "num"), Opt("TimeFlag", "bool", true), Opt("PollRate", "num")], call =>
        {
            RapidTwinController c = call.Machine.Task.Controller;
            if (call.Has(0) && call.Machine.Task.IsMotionTask)
            {
                c.Arm.FinishBlend(call.Machine.Task.CancellationToken);
            }
            double poll = call.Has(4) ? call.Num(4) : DefaultPollSeconds;
            if (poll < 0.04)
            {
                throw ArgumentError(call, $"WaitUntil: the poll rate {RapidValues.FormatNumber(poll)} s is below 0.04 s");
            }
            double max = call.Has(2) ? call.Num(2) : double.PositiveInfinity;
            double waited = 0;
            if (call.Has(3))
            {
                call.Set(3, false);
            }
            while (!(bool)call.Value(1))
            {
                if (waited >= max)
                {
                    if (call.Has(3))
                    {
                        call.Set(3, true);
                        return;
                    }
                    throw call.Error(RapidErrorNumbers.WaitMaxTime, "WaitUntil: the condition did not come true within \\MaxTime");
                }
                Poll(call, poll);
                waited += poll;
            }
        }),
        Function("OpMode", "symnum", [], call => call.Machine.Task.Controller.OperationMode.ToUpperInvariant() switch
        {
            "AUTO" => 1.0,
            "MANR" => 2.0,
            "MANF" => 3.0,
            _ => 0.0,
        }),
        Function("RunMode", "symnum", [Sw("Main")], _ => 1.0),
        Function("RobOS", "bool", [], _ => false), // the twin stands in for a virtual controller (RobotStudio), where RobOS is FALSE
        // TRUE while the motion is held (StopMove, or a TriggCheckIO \StopMove), whichever task held it.
        Function("IsStopMoveAct", "bool", [Sw("FromMoveTask"), Sw("FromNonMoveTask")], call => call.Machine.Task.Controller.Arm.IsHeld),
        Instruction("Incr", [P("Name", "num", true)], call => call.Set(0, (double)call.Value(0) + 1)),
        Instruction("Decr", [P("Name", "num", true)], call => call.Set(0, (double)call.Value(0) - 1)),
        Instruction("Add", [P("Name", "num", true), P("AddValue", "num")], call => call.Set(0, (double)call.Value(0) + call.Num(1))),
        Instruction("Clear", [P("Name", "num", true)], call => call.Set(0, 0.0)),
        Instruction("Set", [P("Signal", "signaldo")], call => SetBit(call, true)),
        Instruction("Reset", [P("Signal", "signaldo")], call => SetBit(call, false)),
        Function("Offs", "robtarget", [P("Point", "robtarget"), P("XOffset", "num"), P("YOffset", "num"), P("ZOffset", "num")], call =>
        {
            var target = (RapidRecord)RapidValues.Copy(call.Value(0));
            var trans = (RapidRecord)target.Fields[0];
            for (int i = 0; i < 3; i++)
            {
                trans.Fields[i] = (double)trans.Fields[i] + call.Num(i + 1);
            }
            return target;
        }),
        Function("Dim", "num", [P("ArrPar", null, true), P("DimNo", "num")], call =>
        {
            if (call.Value(0) is not RapidArray array)
            {
                throw ArgumentError(call, "Dim: the data is not an array");
            }
            int d = (int)call.Num(1);
            return d >= 1 && d <= array.Dimensions.Length ? (double)array.Dimensions[d - 1]
                : throw call.Error(RapidErrorNumbers.OutOfBounds, $"Dim: the array has no dimension {d}");
        }),
        Function("CDate", "string", [], call => call.Machine.Task.Controller.Options.Time.GetLocalNow().ToString("yyyy-MM-dd", CultureInfo.InvariantCulture)),
        Function("CTime", "string", [], call => call.Machine.Task.Controller.Options.Time.GetLocalNow().ToString("HH:mm:ss", CultureInfo.InvariantCulture)),
    ];

    /// <summary>
    /// The global data named by GetDataVal's or SetDataVal's Object (of \TaskName's task when given), which must be of the type of
    /// parameter <paramref name="valueParameter"/>'s argument: ERR_SYM_ACCESS when there is none, ERR_SYMBOL_TYPE for another type.
    /// </summary>
    private static RapidCell DataNamed(RapidCall call, int valueParameter)
    {
        string name = call.Str(0);
        RapidTask task = call.Machine.Task;
        if (call.Has(3))
        {
            string taskName = call.Str(3);
            task = task.Controller.TaskNames.Contains(taskName, StringComparer.OrdinalIgnoreCase) ? task.Controller.Task(taskName)
                : throw call.Error(RapidErrorNumbers.ByName["ERR_TASKNAME"], $"the task '{taskName}' does not exist");
        }
        if (!task.Program.Globals.TryGetValue(name, out RapidCell? cell) && !task.Program.ModuleData.TryGetValue(name, out cell))
        {
            throw call.Error(RapidErrorNumbers.SymAccess, $"no data named '{name}' in the task {task.Name}");
        }
        if (call.TypeOf(valueParameter) is { } type && !type.Accepts(cell.Type))
        {
            throw call.Error(RapidErrorNumbers.SymbolType, $"'{name}' is a {cell.Type}, not a {type}");
        }
        return cell;
    }

    /// <summary>Waits one poll: on the wall clock for a background task, on the program's clock (and briefly on the wall clock) for the motion task.</summary>
    private static void Poll(RapidCall call, double seconds)
    {
        RapidTask task = call.Machine.Task;
        RapidTwinController c = task.Controller;
        if (!task.IsMotionTask)
        {
            c.Clock.WaitWall(seconds, task.CancellationToken);
        }
        else if (c.Options.RealTime)
        {
            c.Clock.WaitAside(seconds, task.CancellationToken);
        }
        else
        {
            c.Clock.Wait(seconds, task.CancellationToken);
            Twin.TwinWait.Blocking();
            task.CancellationToken.WaitHandle.WaitOne(1); // another task may be the one to make the condition true (ends at once when stopped)
        }
        task.CancellationToken.ThrowIfCancellationRequested();
        task.RunPendingTraps(); // an interrupt is served while the task waits (the trap may be what makes the condition true)
    }

    private static void SetBit(RapidCall call, bool on)
    {
        (string name, int index) = Signal(call, 0, "do");
        RapidTwinController c = call.Machine.Task.Controller;
        c.SetBit("do", index, on);
        c.Arm.Record(call.Line, TwinTraceKind.Output, $"{name} = {(on ? 1 : 0)}");
    }
}

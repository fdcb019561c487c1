namespace Machina.Simulation.Rapid;

/// <summary>Writes to the IO configuration's signals, from a program, RWS or a sensor: a change reaches the tasks' signal interrupts.</summary>
internal sealed partial class RapidTwinController
{
    /// <summary>Sets digital signal <paramref name="index"/> of <paramref name="bank"/> ("do" or "di"); a change queues the traps ordered on it.</summary>
    public void SetBit(string bank, int index, bool on)
    {
        bool changed;
        lock (_signalGate)
        {
            changed = Io.GetBit(bank, index) != on;
            Io.SetBit(bank, index, on);
        }
        if (!changed)
        {
            return;
        }
        RapidTask[] tasks;
        lock (_gate)
        {
            tasks = [.. _tasks.Values];
        }
        foreach (RapidTask task in tasks)
        {
            task.PostSignal(bank, index, on);
        }
    }

    /// <summary>Sets numeric signal <paramref name="index"/> of <paramref name="bank"/> ("ao" or "ai").</summary>
    public void SetNumber(string bank, int index, double value) => Io.SetNumber(bank, index, value);

    /// <summary>Sets the signal named <paramref name="name"/> (digital: 0 or 1); false when the IO configuration has none.</summary>
    public bool SetSignal(string name, double value)
    {
        if (Signal(name) is not { } s)
        {
            return false;
        }
        if (s.Bank[0] == 'd')
        {
            SetBit(s.Bank, s.Index, value != 0);
        }
        else
        {
            SetNumber(s.Bank, s.Index, value);
        }
        return true;
    }
}

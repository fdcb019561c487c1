namespace Machina.Simulation.Rapid;

/// <summary>Late binding (RAPID kernel, "Procedure call": <c>%"name"% args;</c>): the procedure is found by name when the call runs.</summary>
internal sealed partial class RapidMachine
{
    /// <summary>
    /// The procedure a late-bound call names now, with its arguments matched to its parameters: ERR_REFUNKPRC when the task has no
    /// procedure of that name, ERR_CALLPROC when it is not a procedure or the arguments do not fit it.
    /// </summary>
    private RapidCallTarget LateTarget(RapidLateCall late, RapidFrame frame)
    {
        string name = (string)Evaluate(late.Name, frame);
        if (late.Last is { Routine: { } last } cached && last.Name.Equals(name, StringComparison.OrdinalIgnoreCase))
        {
            return cached;
        }
        RapidRoutine routine = Task.Program.Find(name)
            ?? throw new RapidRuntimeException(RapidErrorNumbers.ByName["ERR_REFUNKPRC"], late.Line, $"late binding: the task has no procedure '{name}'");
        if (routine.Kind != RapidRoutineKind.Proc)
        {
            throw CallError(late, $"late binding: '{name}' is not a procedure");
        }
        int[] map = new int[routine.Parameters.Count];
        Array.Fill(map, -1);
        int next = 0;
        for (int k = 0; k < late.Args.Length; k++)
        {
            RapidArg arg = late.Args[k];
            int p;
            if (arg.Name is null)
            {
                while (next < map.Length && routine.Parameters[next].Optional)
                {
                    next++;
                }
                p = next < map.Length ? next++ : throw CallError(late, $"late binding: too many arguments for '{name}'");
            }
            else
            {
                p = routine.Parameters.FindIndex(x => x.Optional && x.Name.Equals(arg.Name, StringComparison.OrdinalIgnoreCase));
                if (p < 0 || map[p] >= 0)
                {
                    throw CallError(late, $"late binding: '{name}' has no optional argument '\\{arg.Name}' (or it is given twice)");
                }
            }
            if (routine.Parameters[p].IsSwitch != (arg.Value is null) || (routine.Parameters[p].Mode != RapidParamMode.In && arg.Value is not RapidName))
            {
                throw CallError(late, $"late binding: the argument '{routine.Parameters[p].Name}' of '{name}' does not fit its parameter");
            }
            map[p] = k;
        }
        for (int p = 0; p < map.Length; p++)
        {
            if (!routine.Parameters[p].Optional && map[p] < 0)
            {
                throw CallError(late, $"late binding: the argument '{routine.Parameters[p].Name}' of '{name}' is missing");
            }
        }
        var target = new RapidCallTarget(null, routine, map);
        late.Last = target;
        return target;
    }

    private static RapidRuntimeException CallError(RapidLateCall late, string message) => new(RapidErrorNumbers.ByName["ERR_CALLPROC"], late.Line, message);
}

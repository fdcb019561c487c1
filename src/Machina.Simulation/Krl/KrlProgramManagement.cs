namespace Machina.Simulation.Krl;

/// <summary>
/// What programs read of the controller's program management (KUKA System Software, system variables): the state of the
/// robot interpreter's program ($PRO_STATE1) and of the submit interpreter's ($PRO_STATE0), of type PRO_STATE (#P_FREE no program
/// selected, #P_RESET selected and reset, #P_ACTIVE running, #P_STOP stopped, #P_END at its END), and the controller's
/// millisecond clock ($ROB_TIMER). The commands that select and start, stop, reset or cancel the robot program (CWRITE on the
/// command channel $CMD: RUN, STOP, RESET, CANCEL) act on the robot interpreter (<see cref="KrlTwinController.Command"/>).
/// </summary>
internal static class KrlProgramManagement
{
    /// <summary>STATE_T, the state CWRITE and CREAD write: RET1 (#CMD_OK, #CMD_ABORT…), HITS and LENGTH.</summary>
    public static KrlType StateType { get; } = KrlType.Struct("STATE_T", ("RET1", KrlType.Enum), ("HITS", KrlType.Int), ("LENGTH", KrlType.Int));

    /// <summary>How many arguments CWRITE takes after its format at most on the twin (each one is read, none is used).</summary>
    private const int MaxFormatArguments = 10;

    /// <summary>Adds $PRO_STATE0, $PRO_STATE1, $ROB_TIMER, the channel $CMD and CWRITE to <paramref name="environment"/>.</summary>
    public static void AddTo(KrlEnvironment environment, KrlTwinController controller)
    {
        void Add(KrlCell cell) => environment.System[cell.Name] = cell;
        Add(new KrlCell("$PRO_STATE1", KrlType.Enum, new KrlEnumValue("P_FREE")) { ReadOnly = true, Read = () => new KrlEnumValue(controller.RobotProgramState) });
        Add(new KrlCell("$PRO_STATE0", KrlType.Enum, new KrlEnumValue("P_FREE")) { ReadOnly = true, Read = () => new KrlEnumValue(controller.SubmitProgramState) });
        Add(new KrlCell("$ROB_TIMER", KrlType.Int, 0) { ReadOnly = true, Read = () => KrlValues.Box(controller.RobotTimerMs()) });
        // A channel's name for CWRITE and CREAD; its value means nothing to a program.
        Add(new KrlCell("$CMD", KrlType.Int, 0) { ReadOnly = true });
        KrlBuiltinParameter any = new(null, Optional: true);
        environment.Builtins["CWRITE"] = new KrlBuiltin("CWRITE", null,
            [new(KrlType.Int), new(StateType, IsOut: true), new(KrlType.Enum), KrlBuiltinParameter.Text, .. Enumerable.Repeat(any, MaxFormatArguments)],
            (_, a) => Write(controller, (KrlPlace)a[1], Text(a[3])));
    }

    /// <summary>
    /// CWRITE on $CMD: the robot interpreter's program management (<see cref="KrlTwinController.Command"/>), its answer in the
    /// state's RET1 (HITS and LENGTH 0); a command the twin does not know stops the program that wrote it, with why.
    /// </summary>
    private static object? Write(KrlTwinController controller, KrlPlace state, string command)
    {
        string ret = controller.Command(command) ?? throw new KrlRuntimeException(
            $"CWRITE($CMD, …, \"{command}\") is not supported by the twin: of the program management commands it knows RUN, STOP, RESET and CANCEL");
        state.Set(new KrlStructValue(StateType, [new KrlEnumValue(ret), KrlValues.Box(0), KrlValues.Box(0)]));
        return null;
    }

    private static string Text(object value) => value is string s ? s : KrlValues.Text((KrlArrayValue)value).TrimEnd();
}

namespace Machina;

/// <summary>
/// A driver program that halts because its instruction stream broke (an instruction's values did not arrive within
/// <see cref="ValuesTimeout"/> of its header, a code it does not know: the link's fault, not the instruction's) first writes
/// its instance number negated to output_int_register_26 (docs/protocol-ur.md §5). The host then reports a lost link, as
/// for a dropped socket, and not a failed action: connecting again resumes from the registers, and the instruction that
/// was cut runs then.
/// </summary>
internal sealed partial class UrDriver
{
    private int _streamBroken;

    /// <summary>True when RTDE shows that this connection's program halted on a broken stream (its instance number negated).</summary>
    private bool IsStreamBroken(RtdeSample sample) => sample.Instance == -_instance;

    /// <summary>Reports the broken stream as a lost link, once; no failure is reported after it.</summary>
    private void OnStreamBroken()
    {
        if (Interlocked.Exchange(ref _streamBroken, 1) != 0)
        {
            return;
        }
        Interlocked.Exchange(ref _programFailed, 1);
        string seconds = Num.G(ValuesTimeout.TotalSeconds);
        Log.Warning($"The UR driver program (instance {_instance.ToString(Num.Inv)}) halted on a broken instruction stream (RTDE output_int_register_{UrWire.InstanceRegister.ToString(Num.Inv)} = {(-_instance).ToString(Num.Inv)}).");
        OnClosed(new RobotConnectionException(
            $"the driver program stopped because its instruction stream broke: an instruction did not arrive whole within {seconds} s (a stalled link), " +
            "or the stream was out of step. Nothing of that instruction ran; connect again to resume."));
    }
}

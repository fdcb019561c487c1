namespace Machina.Simulation.Twin;

/// <summary>
/// What a virtual controller's state shows of its twin, the part every brand maps the same way: the outputs that are on (digital
/// outputs set, analog outputs other than 0, by the name the brand's host uses) and the arm where it is, with its tool.
/// </summary>
internal sealed class TwinObservation
{
    private readonly Dictionary<string, bool> _digital = new();
    private readonly Dictionary<string, double> _analog = new();

    /// <summary>Shows digital output <paramref name="name"/> when it is on.</summary>
    public void Digital(string name, bool on)
    {
        if (on)
        {
            _digital[name] = true;
        }
    }

    /// <summary>Shows analog output <paramref name="name"/> when it is not 0.</summary>
    public void Analog(string name, double value)
    {
        if (value != 0)
        {
            _analog[name] = value;
        }
    }

    /// <summary>Shows each digital output of <paramref name="bank"/> that is on, named <paramref name="prefix"/> and its number from <paramref name="first"/>.</summary>
    public void DigitalBank(TwinIo io, string bank, string prefix, int first)
    {
        Span<bool> bits = stackalloc bool[io.Count(bank)];
        io.ReadBits(bank, bits);
        for (int i = 0; i < bits.Length; i++)
        {
            if (bits[i])
            {
                Digital(prefix + (i + first).ToString(Num.Inv), true);
            }
        }
    }

    /// <summary>Shows each analog output of <paramref name="bank"/> that is not 0, named by its number from <paramref name="first"/>.</summary>
    public void AnalogBank(TwinIo io, string bank, int first)
    {
        Span<double> values = stackalloc double[io.Count(bank)];
        io.ReadNumbers(bank, values);
        for (int i = 0; i < values.Length; i++)
        {
            Analog((i + first).ToString(Num.Inv), values[i]);
        }
    }

    /// <summary>
    /// <paramref name="basis"/> with the arm at <paramref name="joints"/> carrying <paramref name="tool"/> (the TCP through the arm's
    /// kinematics; no tool when it is the flange itself) and the outputs shown.
    /// </summary>
    public TState Apply<TState>(TState basis, TwinArm arm, Joints joints, Pose tool) where TState : VirtualRobotState
    {
        Pose tcp = arm.Model.Kinematics.Forward(joints) * tool;
        return (TState)(basis with
        {
            Position = tcp.Position,
            Rotation = tcp.Rotation,
            Joints = joints,
            Tool = tool.Position == Vector.Zero && tool.Rotation.IsSimilar(Rotation.Identity, 1e-9) ? null : tool,
            DigitalOutputs = _digital,
            AnalogOutputs = _analog,
        });
    }
}

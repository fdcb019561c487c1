using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>Settings of a KRL twin controller.</summary>
internal sealed class KrlTwinOptions
{
    /// <summary>The arm model (default KR 6 R900 sixx, as the virtual KUKA).</summary>
    public RobotModel Model { get; init; } = RobotModels.Get("KR 6 R900 sixx");

    /// <summary>The joints (degrees) the arm starts at.</summary>
    public Joints StartJoints { get; init; } = new(0, -90, 90, 0, 90, 0);

    /// <summary>The time source for real-time motion and waits.</summary>
    public TimeProvider Time { get; init; } = TimeProvider.System;

    /// <summary>True: motion and waits take their time on <see cref="Time"/>; false: they return at once (program time still adds up).</summary>
    public bool RealTime { get; init; }

    /// <summary>The signals of the IO configuration ($CONFIG.DAT's SIGNAL name $OUT[n]): name and output number.</summary>
    public IReadOnlyList<(string Name, int Output)> Signals { get; init; } = [];

    /// <summary>$VEL.CP (m/s) that BAS(#INITMOV) sets and that the program starts with.</summary>
    public double DefaultCpVelocity { get; init; } = 2;

    /// <summary>$ACC.CP (m/s²) that BAS(#INITMOV) sets and that the program starts with.</summary>
    public double DefaultCpAcceleration { get; init; } = 2.3;

    /// <summary>Axis speed (deg/s) at $VEL_AXIS = 100 when the model gives none.</summary>
    public double DefaultAxisSpeed { get; init; } = 180;

    /// <summary>Seconds for an axis to reach its full speed at $ACC_AXIS = 100.</summary>
    public double AxisRampSeconds { get; init; } = 0.3;

    /// <summary>The folder that holds the EthernetKRL XML configurations (null: the drivers/kuka configurations are given to the controller directly).</summary>
    public string? EkiConfigurationFolder { get; init; }

    /// <summary>How many steps of the arm's trace are kept at least (0: all of them).</summary>
    public int MaxTrace { get; init; }

    /// <summary>Where a controller around the twin watches and shapes the EthernetKRL channels (null: none).</summary>
    public IEkiSeam? Seam { get; init; }

    /// <summary>The address EthernetKRL server channels listen on (loopback for tests).</summary>
    public System.Net.IPAddress ListenAddress { get; init; } = System.Net.IPAddress.Loopback;

    /// <summary>The interpreter's budgets (nesting, expression size, calls, steps, arrays, file size).</summary>
    public TwinLimits Limits { get; init; } = TwinLimits.Default;
}

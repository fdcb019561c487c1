using Machina.Simulation.Twin;

namespace Machina.Simulation.Krl;

/// <summary>Settings of a KRL twin controller.</summary>
internal sealed record KrlTwinOptions : TwinOptions
{
    /// <summary>Settings with the virtual KUKA's arm: a KR 6 R900 sixx in its home position.</summary>
    public KrlTwinOptions()
        : base(RobotModels.Get("KR 6 R900 sixx"), new Joints(0, -90, 90, 0, 90, 0))
    {
    }

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

    /// <summary>Where a controller around the twin watches and shapes the EthernetKRL channels (null: none).</summary>
    public IEkiSeam? Seam { get; init; }

    /// <summary>The address EthernetKRL server channels listen on (loopback for tests).</summary>
    public System.Net.IPAddress ListenAddress { get; init; } = System.Net.IPAddress.Loopback;
}

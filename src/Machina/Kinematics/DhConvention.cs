namespace Machina;

/// <summary>Which of the two Denavit–Hartenberg conventions a table follows (see <see cref="RobotModel.FromDh"/>).</summary>
public enum DhConvention
{
    /// <summary>Standard (distal) DH, as in Denavit–Hartenberg and Spong: each link is Rz(θ)·Tz(d)·Tx(a)·Rx(α).</summary>
    Standard,

    /// <summary>Modified (proximal) DH, as in Craig: each link is Rx(α<sub>i−1</sub>)·Tx(a<sub>i−1</sub>)·Rz(θ)·Tz(d).</summary>
    Modified,
}

namespace Machina.Simulation.Krl;

/// <summary>
/// The line an interpreter runs now, as the traces of what it writes carry it (<see cref="KrlTwinController.Line"/>): the robot
/// interpreter and each submit interpreter have their own, each written by its interpreter's thread alone, so that one
/// interpreter's statements never move the line another's output is traced at.
/// </summary>
internal sealed class KrlRunningLine
{
    /// <summary>The line; written by the interpreter's thread before each statement.</summary>
    public int Value;
}

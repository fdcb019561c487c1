namespace Machina;

public sealed partial class Robot
{
    /// <summary>Handler of <see cref="ActionIssued"/>: the robot and the action just accepted (the original's delegate name).</summary>
    public delegate void ActionIssuedHandler(object? sender, ActionIssuedArgs args);

    /// <summary>Handler of <see cref="ActionReleased"/>: the robot and the action just sent to the controller.</summary>
    public delegate void ActionReleasedHandler(object? sender, ActionReleasedArgs args);

    /// <summary>Handler of <see cref="ActionExecuted"/>: the robot and the action the controller reports as executed.</summary>
    public delegate void ActionExecutedHandler(object? sender, ActionExecutedArgs args);

    /// <summary>Handler of <see cref="MotionUpdate"/>: the robot and where the controller reports it is.</summary>
    public delegate void MotionUpdateHandler(object? sender, MotionUpdateArgs args);
}

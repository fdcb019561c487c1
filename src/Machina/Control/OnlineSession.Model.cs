namespace Machina;

internal sealed partial class OnlineSession
{
    /// <summary>
    /// Takes the arm model the controller reported in its handshake (on the loop, under the issue lock, before the cursors are
    /// set): a robot without a model gets it, so every joint move has a pose (forward kinematics) and every motion is checked.
    /// A model the user chose wins; when the controller names another arm, the warning names both. A name outside the
    /// catalogue is logged and changes nothing.
    /// </summary>
    private void LearnModel(DeviceHandshake handshake, RobotCursor issue)
    {
        if (handshake.ModelName is not string reported)
        {
            return;
        }
        RobotModel? current = issue.Model;
        if (handshake.Model is not RobotModel learned)
        {
            Log(current is null ? LogLevel.WARNING : LogLevel.INFO, current is null
                ? $"The controller reports the arm \"{reported}\", which is not in Machina's catalogue: the robot has no model, so joint moves "
                    + "have no known pose. Choose the model with SetModel before connecting (see Robot.Models)."
                : $"The controller reports the arm \"{reported}\", which is not in Machina's catalogue; the robot keeps its model {current.Name}.");
            return;
        }
        if (current is null)
        {
            _execution.Model = learned;
            _release.Model = learned;
            issue.Model = learned;
            Log(LogLevel.INFO, $"The controller reports the arm \"{reported}\": the robot's model is now {learned.Name}.");
            return;
        }
        if (!string.Equals(current.Name, learned.Name, StringComparison.Ordinal))
        {
            Log(LogLevel.WARNING, $"The robot's model is {current.Name}, but the controller reports the arm \"{reported}\" ({learned.Name}). "
                + $"Machina keeps {current.Name}, the model you chose, for its poses and checks: if the controller is right, disconnect, "
                + $"call SetModel(\"{learned.Name}\") on a new robot and connect again.");
        }
    }
}

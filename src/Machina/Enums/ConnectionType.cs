namespace Machina;

/// <summary>Who starts the driver program on the controller.</summary>
public enum ConnectionType
{
    /// <summary>The user loads and starts the driver on the controller, then connects (default).</summary>
    User,
    /// <summary>Machina installs and starts the driver itself on an ABB, through its Robot Web Services, at each Connect (see Robot.InstallDriverAsync).</summary>
    Machina,
}

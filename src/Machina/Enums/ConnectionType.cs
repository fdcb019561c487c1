namespace Machina;

/// <summary>Who starts the driver program on the controller.</summary>
public enum ConnectionType
{
    /// <summary>The user loads and starts the driver on the controller, then connects (default).</summary>
    User,
    /// <summary>Machina loads the driver itself (not available in this version).</summary>
    Machina,
}

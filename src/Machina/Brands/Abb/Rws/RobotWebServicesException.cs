namespace Machina;

/// <summary>
/// An ABB controller's Robot Web Services refused a request or could not be reached; the message says what was asked and the
/// controller's reason (for example: not in automatic mode, mastership held by the FlexPendant, a module that does not load).
/// </summary>
public sealed class RobotWebServicesException : MachinaException
{
    /// <summary>Creates the exception with a message, the HTTP status (0 when there was no answer) and the controller's return code.</summary>
    public RobotWebServicesException(string message, int httpStatus, long? controllerCode, Exception? innerException = null)
        : base(message, innerException)
    {
        HttpStatus = httpStatus;
        ControllerCode = controllerCode;
    }

    /// <summary>The HTTP status code of the answer (for example 400 or 401), or 0 when the controller did not answer.</summary>
    public int HttpStatus { get; }

    /// <summary>The controller's own return code from the answer (RobotWare return codes), when it gave one.</summary>
    public long? ControllerCode { get; }
}

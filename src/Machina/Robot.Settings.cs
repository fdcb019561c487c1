namespace Machina;

public sealed partial class Robot
{
    /// <summary>Changes the speed of the following motions by an amount, mm/s.</summary>
    public bool Speed(double speedInc) => Issue(new ActionSpeed(Arg.Finite(speedInc), true));

    /// <summary>Sets the speed of the following motions, mm/s (also used as deg/s for rotations).</summary>
    public bool SpeedTo(double speed) => Issue(new ActionSpeed(speed, false));

    /// <summary>Changes the acceleration of the following motions by an amount, mm/s².</summary>
    public bool Acceleration(double accelerationInc) => Issue(new ActionAcceleration(Arg.Finite(accelerationInc), true));

    /// <summary>Sets the acceleration of the following motions, mm/s² (0 = the controller's default).</summary>
    public bool AccelerationTo(double acceleration) => Issue(new ActionAcceleration(acceleration, false));

    /// <summary>Changes the blend radius of the following motions by an amount, mm.</summary>
    public bool Precision(double radiusInc) => Issue(new ActionPrecision(Arg.Finite(radiusInc), true));

    /// <summary>Sets the blend radius of the following motions, mm: how close the robot must pass by each target (0 = exactly).</summary>
    public bool PrecisionTo(double radius) => Issue(Arg.Renamed("precision", nameof(radius), radius, static r => new ActionPrecision(r, false)));

    /// <summary>Chooses linear or joint motion for the following moves.</summary>
    public bool MotionMode(MotionType motionType) => Issue(new ActionMotionMode(motionType));

    /// <summary>Chooses "linear" or "joint" motion for the following moves (any letter case).</summary>
    public bool MotionMode(string motionType) => MotionMode(EnumText.Parse<MotionType>(motionType, "motion type", nameof(motionType)));

    /// <summary>Chooses the frame of the following relative actions: the world, or the tool itself.</summary>
    public bool Coordinates(ReferenceCS referenceCS) => Issue(new ActionCoordinates(referenceCS));

    /// <summary>Chooses the frame of the following relative actions: "world" or "local" (any letter case).</summary>
    public bool Coordinates(string referenceCS) => Coordinates(EnumText.Parse<ReferenceCS>(referenceCS, "coordinate system", nameof(referenceCS)));

    /// <summary>Saves speed, acceleration, precision, motion type, reference frame and extrusion rate, to restore them with <see cref="PopSettings"/>.</summary>
    public bool PushSettings() => Issue(new ActionPushPop(true));

    /// <summary>Restores the settings saved by the last <see cref="PushSettings"/>.</summary>
    public bool PopSettings() => Issue(new ActionPushPop(false));

    /// <summary>Pauses for a time, milliseconds.</summary>
    public bool Wait(long timeMillis) => Issue(Arg.Renamed("millis", nameof(timeMillis), timeMillis, static t => new ActionWait(t)));

    /// <summary>Shows a message on the robot's teach pendant or screen.</summary>
    public bool Message(string message) => Issue(new ActionMessage(message));

    /// <summary>Adds a comment to the compiled program.</summary>
    public bool Comment(string comment) => Issue(new ActionComment(comment));

    /// <summary>Inserts a line of the robot's own language into the program as it is (for experts; Machina cannot check it).</summary>
    public bool CustomCode(string statement, bool isDeclaration = false) => Issue(new ActionCustomCode(statement, isDeclaration));
}

namespace Machina;

/// <summary>The kind of an action. The numbers are fixed: some driver protocols send them.</summary>
public enum ActionType
{
    /// <summary>Not set.</summary>
    Undefined = 0,
    /// <summary>Move the tool tip.</summary>
    Translation = 1,
    /// <summary>Rotate the tool.</summary>
    Rotation = 2,
    /// <summary>Move and rotate the tool.</summary>
    Transformation = 3,
    /// <summary>Set the joint angles.</summary>
    Axes = 4,
    /// <summary>Show a message.</summary>
    Message = 5,
    /// <summary>Pause.</summary>
    Wait = 6,
    /// <summary>Change speed.</summary>
    Speed = 7,
    /// <summary>Change acceleration.</summary>
    Acceleration = 8,
    /// <summary>Change precision (blend radius).</summary>
    Precision = 9,
    /// <summary>Change linear/joint motion.</summary>
    MotionMode = 10,
    /// <summary>Change the reference frame of relative actions.</summary>
    Coordinates = 11,
    /// <summary>Save or restore settings.</summary>
    PushPop = 12,
    /// <summary>A comment in the program.</summary>
    Comment = 13,
    /// <summary>Define a tool.</summary>
    DefineTool = 14,
    /// <summary>Attach a tool.</summary>
    AttachTool = 15,
    /// <summary>Detach the tool.</summary>
    DetachTool = 16,
    /// <summary>Write a digital output.</summary>
    IODigital = 17,
    /// <summary>Write an analog output.</summary>
    IOAnalog = 18,
    /// <summary>Set a temperature.</summary>
    Temperature = 19,
    /// <summary>Turn extrusion on or off.</summary>
    Extrusion = 20,
    /// <summary>Change the extrusion rate.</summary>
    ExtrusionRate = 21,
    /// <summary>Start-up or shut-down sequence.</summary>
    Initialization = 22,
    /// <summary>Move an external axis.</summary>
    ExternalAxis = 23,
    /// <summary>Raw code in the robot's language.</summary>
    CustomCode = 24,
    /// <summary>Arm angle of a 7-axis arm.</summary>
    ArmAngle = 25,
    /// <summary>Circular motion.</summary>
    ArcMotion = 26,
    /// <summary>Wait for a digital input.</summary>
    WaitDigital = 27,
    /// <summary>Read a digital or analog input.</summary>
    ReadInput = 28,
}

namespace Machina;

/// <summary>Instruction codes of requests sent by the host to the RAPID driver (spec online §6.3).</summary>
internal enum AbbInstructionCode
{
    MoveL = 1,
    MoveJ = 2,
    MoveAbsJ = 3,
    Speed = 4,
    Zone = 5,
    WaitTime = 6,
    TPWrite = 7,
    Tool = 8,
    NoTool = 9,
    SetDO = 10,
    SetAO = 11,
    ExternalAxesAll = 12,
    Acceleration = 13,
    SingularityArea = 14,
    ExternalAxesRobTarget = 15,
    ExternalAxesJointTarget = 16,
    CustomAction = 17,
    WorkObject = 18,
    NoWorkObject = 19,
    WaitDI = 20,
    ReadDI = 21,
    ReadAI = 22,
    MoveC = 30,
    ArcThroughOrientation = 31,
    StopExecution = 100,
    GetInfo = 101,
    SetConfiguration = 102,
    SetMotionUpdateInterval = 103,
}

namespace Machina;

public sealed partial class Robot
{
    /// <summary>Adds a tool to the robot's tool library, to attach it later by name.</summary>
    public bool DefineTool(Tool tool) => Issue(new ActionDefineTool(tool));

    /// <summary>Defines a tool from its tip position (mm) and tip orientation; weight 1 kg, centre of gravity halfway to the tip.</summary>
    public bool DefineTool(string name, Vector tcpPosition, Rotation tcpOrientation) =>
        DefineTool(Tool.Create(name, tcpPosition, tcpOrientation));

    /// <summary>Defines a tool from its tip position (mm), tip orientation, weight (kg) and centre of gravity (mm).</summary>
    public bool DefineTool(string name, Vector tcpPosition, Rotation tcpOrientation, double weightKg, Vector centerOfGravity) =>
        DefineTool(Tool.Create(name, tcpPosition, tcpOrientation, Arg.Renamed("weight", nameof(weightKg), weightKg, static w => Tool.CheckWeight(w)), centerOfGravity));

    /// <summary>Defines a tool from numbers: tip (mm), tip frame X and Y axes, weight (kg) and centre of gravity (mm).</summary>
    public bool DefineTool(string name, double tcpX, double tcpY, double tcpZ,
        double tcp_vX0, double tcp_vX1, double tcp_vX2, double tcp_vY0, double tcp_vY1, double tcp_vY2,
        double weight, double cogX, double cogY, double cogZ) =>
        DefineTool(Tool.Create(name, Arg.Vector(tcpX, tcpY, tcpZ),
            Arg.FromAxes(Arg.Vector(tcp_vX0, tcp_vX1, tcp_vX2), Arg.Vector(tcp_vY0, tcp_vY1, tcp_vY2), nameof(tcp_vX0), nameof(tcp_vY0)),
            Tool.CheckWeight(weight), Arg.Vector(cogX, cogY, cogZ)));

    /// <summary>Attaches a defined tool: from now on positions refer to its tip.</summary>
    public bool AttachTool(string toolName) => Issue(Arg.Renamed("name", nameof(toolName), toolName, static n => new ActionAttachTool(n)));

    /// <summary>Detaches the tool: positions refer to the flange again.</summary>
    public bool DetachTool() => Issue(new ActionDetachTool());

    /// <summary>Old name: defines and attaches a tool. Use <see cref="DefineTool(Tool)"/> and <see cref="AttachTool"/>.</summary>
    [Obsolete("Use DefineTool(tool) and then AttachTool(name).")]
    public bool Attach(Tool tool) => DefineTool(tool) && AttachTool(tool.Name);

    /// <summary>Old name of <see cref="DetachTool"/>.</summary>
    [Obsolete("Use DetachTool().")]
    public bool Detach() => DetachTool();

    /// <summary>Turns digital output number <paramref name="pinNumber"/> on or off (of the tool, when <paramref name="toolPin"/>).</summary>
    public bool WriteDigital(int pinNumber, bool isOn, bool toolPin = false) => WriteDigital(PinText(pinNumber), isOn, toolPin);

    /// <summary>Turns a digital output, given by number or signal name, on or off.</summary>
    public bool WriteDigital(string pinId, bool isOn, bool toolPin = false) => Issue(Arg.Renamed("pin", nameof(pinId), (pinId, isOn, toolPin), static a => new ActionIODigital(a.pinId, a.isOn, a.toolPin)));

    /// <summary>Sets analog output number <paramref name="pinNumber"/> to a value (of the tool, when <paramref name="toolPin"/>).</summary>
    public bool WriteAnalog(int pinNumber, double value, bool toolPin = false) => WriteAnalog(PinText(pinNumber), value, toolPin);

    /// <summary>Sets an analog output, given by number or signal name, to a value.</summary>
    public bool WriteAnalog(string pinId, double value, bool toolPin = false) => Issue(Arg.Renamed("pin", nameof(pinId), (pinId, value, toolPin), static a => new ActionIOAnalog(a.pinId, a.value, a.toolPin)));

    private static string PinText(int pinNumber) => pinNumber >= 0
        ? Num.I(pinNumber)
        : throw new ArgumentOutOfRangeException(nameof(pinNumber), pinNumber, "IO pin numbers cannot be negative.");

    /// <summary>Changes the temperature of a 3D printer part ("extruder", "bed" or "chamber") by an amount, °C.</summary>
    public bool Temperature(double temperature, string devicePart, bool waitToReachTemp = true) =>
        Issue(new ActionTemperature(temperature, EnumText.Parse<RobotPartType>(devicePart, "printer part", nameof(devicePart)), waitToReachTemp, true));

    /// <summary>Sets the temperature of a 3D printer part ("extruder", "bed" or "chamber"), °C, and by default waits until it is reached.</summary>
    public bool TemperatureTo(double temperature, string devicePart, bool waitToReachTemp = true) =>
        Issue(new ActionTemperature(temperature, EnumText.Parse<RobotPartType>(devicePart, "printer part", nameof(devicePart)), waitToReachTemp, false));

    /// <summary>Changes the temperature of a 3D printer part by an amount, °C.</summary>
    public bool Temperature(double temperature, RobotPartType devicePart, bool waitToReachTemp = true) =>
        Issue(new ActionTemperature(temperature, EnumText.RequireDefined(devicePart, nameof(devicePart)), waitToReachTemp, true));

    /// <summary>Sets the temperature of a 3D printer part, °C.</summary>
    public bool TemperatureTo(double temperature, RobotPartType devicePart, bool waitToReachTemp = true) =>
        Issue(new ActionTemperature(temperature, EnumText.RequireDefined(devicePart, nameof(devicePart)), waitToReachTemp, false));

    /// <summary>Changes the extrusion rate by an amount, mm of filament per mm of travel.</summary>
    public bool ExtrusionRate(double rateInc) => Issue(new ActionExtrusionRate(Arg.Finite(rateInc), true));

    /// <summary>Sets the extrusion rate, mm of filament per mm of travel.</summary>
    public bool ExtrusionRateTo(double rate) => Issue(new ActionExtrusionRate(rate, false));

    /// <summary>Turns extrusion on (default) or off for the following moves.</summary>
    public bool Extrude(bool extrude = true) => Issue(new ActionExtrusion(extrude));

    /// <summary>Runs the device's start-up sequence (homing, heating… for 3D printers).</summary>
    public bool Initialize() => Issue(new ActionInitialization(true));

    /// <summary>Runs the device's shut-down sequence.</summary>
    public bool Terminate() => Issue(new ActionInitialization(false));
}

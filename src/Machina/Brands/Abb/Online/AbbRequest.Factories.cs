namespace Machina;

/// <summary>Typed constructors for each instruction, rounding values the way the original host did (spec online §6.2, §6.6).</summary>
internal readonly partial struct AbbRequest
{
    private const int MillimetreDecimals = RapidFacts.MillimetreDecimals;
    private const int QuaternionDecimals = RapidFacts.QuaternionDecimals;
    private const int DegreeDecimals = RapidFacts.MillimetreDecimals;
    private const int KilogramDecimals = 3;

    /// <summary>Code 1 (MoveL) or 2 (MoveJ) to an absolute TCP pose: position in mm (3 decimals), quaternion W X Y Z (4 decimals).</summary>
    public static AbbRequest Move(int id, bool linear, Vector position, Rotation rotation) =>
        new(id, (int)(linear ? AbbInstructionCode.MoveL : AbbInstructionCode.MoveJ), null,
        [
            R(position.X, MillimetreDecimals), R(position.Y, MillimetreDecimals), R(position.Z, MillimetreDecimals),
            R(rotation.W, QuaternionDecimals), R(rotation.X, QuaternionDecimals), R(rotation.Y, QuaternionDecimals), R(rotation.Z, QuaternionDecimals),
        ]);

    /// <summary>Code 3 (MoveAbsJ) to six joint angles in degrees (3 decimals).</summary>
    public static AbbRequest MoveAbsJ(int id, Joints joints) =>
        new(id, (int)AbbInstructionCode.MoveAbsJ, null,
        [
            R(joints.J1, DegreeDecimals), R(joints.J2, DegreeDecimals), R(joints.J3, DegreeDecimals),
            R(joints.J4, DegreeDecimals), R(joints.J5, DegreeDecimals), R(joints.J6, DegreeDecimals),
        ]);

    /// <summary>Code 30 (MoveC): end pose (as <see cref="Move"/>) then the through point in mm (3 decimals).</summary>
    public static AbbRequest MoveC(int id, Vector end, Rotation endRotation, Vector through) =>
        new(id, (int)AbbInstructionCode.MoveC, null,
        [
            R(end.X, MillimetreDecimals), R(end.Y, MillimetreDecimals), R(end.Z, MillimetreDecimals),
            R(endRotation.W, QuaternionDecimals), R(endRotation.X, QuaternionDecimals), R(endRotation.Y, QuaternionDecimals), R(endRotation.Z, QuaternionDecimals),
            R(through.X, MillimetreDecimals), R(through.Y, MillimetreDecimals), R(through.Z, MillimetreDecimals),
        ]);

    /// <summary>
    /// Code 31: the orientation of the next MoveC's through point, quaternion W X Y Z (4 decimals), as the RAPID compiler writes
    /// its CirPoint; sent with id 0 just before the arc's code 30.
    /// </summary>
    public static AbbRequest ArcThroughOrientation(Rotation rotation) =>
        new(0, (int)AbbInstructionCode.ArcThroughOrientation, null,
        [
            R(rotation.W, QuaternionDecimals), R(rotation.X, QuaternionDecimals), R(rotation.Y, QuaternionDecimals), R(rotation.Z, QuaternionDecimals),
        ]);

    /// <summary>Code 4: TCP speed in mm/s, unrounded.</summary>
    public static AbbRequest Speed(int id, double millimetresPerSecond) => One(id, AbbInstructionCode.Speed, millimetresPerSecond);

    /// <summary>Code 5: zone radius in mm, unrounded (0 = fine, stop exactly at each target).</summary>
    public static AbbRequest Zone(int id, double millimetres) => One(id, AbbInstructionCode.Zone, millimetres);

    /// <summary>Code 13: TCP acceleration limit. Takes mm/s² and sends m/s² as RAPID's WorldAccLim expects (fix of bug A4); 0 or less turns the limit off.</summary>
    public static AbbRequest Acceleration(int id, double millimetresPerSecondSquared) =>
        One(id, AbbInstructionCode.Acceleration, millimetresPerSecondSquared * 0.001);

    /// <summary>Code 6: wait. Takes milliseconds and sends seconds, unrounded.</summary>
    public static AbbRequest WaitTime(int id, double milliseconds) => One(id, AbbInstructionCode.WaitTime, milliseconds * 0.001);

    /// <summary>Code 7: show a message on the pendant (text made safe with <see cref="SanitizeText"/>).</summary>
    public static AbbRequest TPWrite(int id, string message) =>
        new(id, (int)AbbInstructionCode.TPWrite, SanitizeText(message), []);

    /// <summary>Code 8: attach a tool: TCP position mm (3), TCP quaternion (4), mass kg (3), centre of gravity mm (3).</summary>
    public static AbbRequest Tool(int id, Vector tcpPosition, Rotation tcpRotation, double weightKg, Vector centerOfGravity) =>
        new(id, (int)AbbInstructionCode.Tool, null,
        [
            R(tcpPosition.X, MillimetreDecimals), R(tcpPosition.Y, MillimetreDecimals), R(tcpPosition.Z, MillimetreDecimals),
            R(tcpRotation.W, QuaternionDecimals), R(tcpRotation.X, QuaternionDecimals), R(tcpRotation.Y, QuaternionDecimals), R(tcpRotation.Z, QuaternionDecimals),
            R(weightKg, KilogramDecimals),
            R(centerOfGravity.X, MillimetreDecimals), R(centerOfGravity.Y, MillimetreDecimals), R(centerOfGravity.Z, MillimetreDecimals),
        ]);

    /// <summary>Code 9: detach the tool (back to tool0, the flange).</summary>
    public static AbbRequest NoTool(int id) => new(id, (int)AbbInstructionCode.NoTool, null, []);

    /// <summary>Code 10: set the digital output named <paramref name="signal"/> to 1 or 0.</summary>
    public static AbbRequest SetDO(int id, string signal, bool on) =>
        new(id, (int)AbbInstructionCode.SetDO, signal, [on ? 1 : 0]);

    /// <summary>
    /// Code 20: wait until the digital input named <paramref name="signal"/> is on (off), at most <paramref name="timeoutMillis"/>
    /// ms (sent in seconds; 0 = no limit). A wait that times out is reported as failure code 3 (<see cref="AbbFailure.WaitTimedOut"/>).
    /// </summary>
    public static AbbRequest WaitDI(int id, string signal, bool on, long timeoutMillis) =>
        new(id, (int)AbbInstructionCode.WaitDI, signal, [on ? 1 : 0, timeoutMillis / 1000.0]);

    /// <summary>
    /// Code 21 (digital) or 22 (analog): read the input named <paramref name="signal"/>; the driver answers <c>$27 id value;</c>
    /// (<see cref="AbbResponseCode.InputRead"/>) just before the acknowledgement.
    /// </summary>
    public static AbbRequest ReadInput(int id, string signal, bool analog) =>
        new(id, (int)(analog ? AbbInstructionCode.ReadAI : AbbInstructionCode.ReadDI), signal, []);

    /// <summary>Code 11: set the analog output named <paramref name="signal"/> to a value, unrounded (sent once: fix of bug A3).</summary>
    public static AbbRequest SetAO(int id, string signal, double value) =>
        new(id, (int)AbbInstructionCode.SetAO, signal, [value]);

    /// <summary>Code 15: external axes of the Cartesian targets; empty axes are sent as 9E9, others in degrees/mm (3 decimals).</summary>
    public static AbbRequest ExternalAxesRobTarget(int id, ExternalAxes axes) => Axes(id, AbbInstructionCode.ExternalAxesRobTarget, axes);

    /// <summary>Code 16: external axes of the joint targets; empty axes are sent as 9E9.</summary>
    public static AbbRequest ExternalAxesJointTarget(int id, ExternalAxes axes) => Axes(id, AbbInstructionCode.ExternalAxesJointTarget, axes);

    /// <summary>Code 103: how often the monitor task reports the robot state, in milliseconds (sent as seconds).</summary>
    public static AbbRequest MotionUpdateInterval(int id, double milliseconds) =>
        One(id, AbbInstructionCode.SetMotionUpdateInterval, milliseconds * 0.001);

    private static AbbRequest One(int id, AbbInstructionCode code, double value) => new(id, (int)code, null, [value]);

    private static AbbRequest Axes(int id, AbbInstructionCode code, ExternalAxes axes)
    {
        Span<double> values = stackalloc double[ExternalAxes.Count];
        for (int i = 0; i < values.Length; i++)
        {
            double? v = axes[i + 1];
            values[i] = v is null ? UnusedAxis : R(v.Value, MillimetreDecimals);
        }
        return new AbbRequest(id, (int)code, null, values);
    }

    private static double R(double value, int decimals) => Math.Round(Num.Finite(value, "value"), decimals);
}

namespace Machina;

internal sealed partial class RobotCursor
{
    /// <summary>
    /// What one action can change, saved before it is applied so that it can be undone (<see cref="Undo"/>) without copying the
    /// whole cursor: every value the cursor holds, and of its collections only what the action writes (the tool it defines, the
    /// output it sets, the top of the settings stack). A value type: taking it allocates nothing.
    /// </summary>
    internal readonly struct UndoPoint
    {
        internal UndoPoint(RobotCursor c, RobotAction action)
        {
            Motion = c.SaveMotion();
            Settings = c.CurrentSettings;
            Tool = c.Tool;
            ExternalAxesCartesian = c.ExternalAxesCartesian;
            ExternalAxesJoints = c.ExternalAxesJoints;
            ArmAngle = c.ArmAngle;
            (Temperature0, Temperature1, Temperature2) = (c.Temperatures[0], c.Temperatures[1], c.Temperatures[2]);
            IsExtruding = c._isExtruding;
            SettingsBeforeLastPop = c.SettingsBeforeLastPop;
            LastAction = c.LastAction;
            LastIssues = c.LastIssues;
            StackDepth = c.SettingsStack.Count;
            StackTop = StackDepth > 0 ? c.SettingsStack.Peek() : default;
            switch (action)
            {
                case ActionDefineTool define:
                    Key = define.Tool.Name;
                    HadEntry = c.Tools.TryGetValue(Key, out Tool? defined);
                    DefinedTool = defined;
                    break;
                case ActionIODigital digital:
                    Key = OutputKey(digital.IsToolPin, digital.PinName);
                    HadEntry = c.DigitalOutputs.TryGetValue(Key, out bool on);
                    Digital = on;
                    break;
                case ActionIOAnalog analog:
                    Key = OutputKey(analog.IsToolPin, analog.PinName);
                    HadEntry = c.AnalogOutputs.TryGetValue(Key, out double value);
                    Analog = value;
                    break;
            }
            Applied = action;
        }

        /// <summary>The action this point was taken for.</summary>
        private RobotAction? Applied { get; }

        private MotionFields Motion { get; }
        private Settings Settings { get; }
        private Tool? Tool { get; }
        private ExternalAxes? ExternalAxesCartesian { get; }
        private ExternalAxes? ExternalAxesJoints { get; }
        private double? ArmAngle { get; }
        private double Temperature0 { get; }
        private double Temperature1 { get; }
        private double Temperature2 { get; }
        private bool IsExtruding { get; }
        private Settings? SettingsBeforeLastPop { get; }
        private RobotAction? LastAction { get; }
        private IReadOnlyList<KinematicIssue> LastIssues { get; }
        private int StackDepth { get; }
        private Settings StackTop { get; }

        /// <summary>The collection entry the action writes (a tool's name, an output's key), or null.</summary>
        private string? Key { get; }
        private bool HadEntry { get; }
        private Tool? DefinedTool { get; }
        private bool Digital { get; }
        private double Analog { get; }

        /// <summary>Puts <paramref name="c"/> back as it was when this point was taken (only the action it was taken for was applied since).</summary>
        internal void Restore(RobotCursor c)
        {
            c.RestoreMotion(Motion);
            c.ApplySettings(Settings);
            c.Tool = Tool;
            c.ExternalAxesCartesian = ExternalAxesCartesian;
            c.ExternalAxesJoints = ExternalAxesJoints;
            c.ArmAngle = ArmAngle;
            (c.Temperatures[0], c.Temperatures[1], c.Temperatures[2]) = (Temperature0, Temperature1, Temperature2);
            c._isExtruding = IsExtruding;
            c.SettingsBeforeLastPop = SettingsBeforeLastPop;
            c.LastAction = LastAction;
            c.LastIssues = LastIssues;
            // A push added one setting, a pop took one away: at most one step either way.
            if (c.SettingsStack.Count > StackDepth)
            {
                c.SettingsStack.Pop();
            }
            else if (c.SettingsStack.Count < StackDepth)
            {
                c.SettingsStack.Push(StackTop);
            }
            switch (Applied)
            {
                case ActionDefineTool:
                    Put(c.Tools, Key!, HadEntry, DefinedTool!);
                    break;
                case ActionIODigital:
                    Put(c.DigitalOutputs, Key!, HadEntry, Digital);
                    break;
                case ActionIOAnalog:
                    Put(c.AnalogOutputs, Key!, HadEntry, Analog);
                    break;
            }
        }

        private static void Put<T>(Dictionary<string, T> entries, string key, bool had, T value)
        {
            if (had)
            {
                entries[key] = value;
            }
            else
            {
                entries.Remove(key);
            }
        }
    }

    /// <summary>The state before <paramref name="action"/> is applied, enough to undo that one action (see <see cref="Undo"/>).</summary>
    internal UndoPoint Mark(RobotAction action) => new(this, action);

    /// <summary>
    /// Undoes the one action applied since <paramref name="point"/> was taken (<see cref="Mark"/>): the cursor is then exactly as it
    /// was, every field. Used online when the wire cannot carry an action the cursor accepted.
    /// </summary>
    internal void Undo(in UndoPoint point) => point.Restore(this);

    /// <summary>The key of an output in <see cref="DigitalOutputs"/> and <see cref="AnalogOutputs"/>.</summary>
    private static string OutputKey(bool toolPin, string pin) => toolPin ? "tool:" + pin : pin;
}

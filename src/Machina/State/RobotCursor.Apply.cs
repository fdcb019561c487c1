using System.Runtime.CompilerServices;
namespace Machina;

internal sealed partial class RobotCursor
{
    /// <summary>Applies an action, or explains why it cannot be applied; on refusal nothing changes.</summary>
    /// <returns>Null on success, else the reason for refusing, in plain words.</returns>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal string? TryApply(RobotAction action)
    {
        _applying = action;
        string? refusal = Apply(action);
        _applying = null;
        return refusal;
    }

    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    private string? Apply(RobotAction action)
    {
        if (Model is RobotModel model)
        {
            LastIssues = NoIssues;
            if (IsMotion(action))
            {
                string? result = ApplyWithModel(action, model);
                if (result is null)
                {
                    LastAction = action;
                }
                return result;
            }
        }
        string? refusal = action switch
        {
            ActionTranslation a => ApplyTranslation(a),
            ActionRotation a => ApplyRotation(a),
            _ => ApplyOther(action),
        };
        if (refusal is null)
        {
            LastAction = action;
        }
        return refusal;
    }

    /// <summary>
    /// Applies any action but a translation or a rotation (the moves of a toolpath). Apart from <see cref="Apply"/>, which the runtime compiles fully optimised at its
    /// first call: that compile of the whole switch was milliseconds of every fresh process's first move, for the rarer actions.
    /// </summary>
    private string? ApplyOther(RobotAction action)
    {
        return action switch
        {
            ActionTransformation a => ApplyTransformation(a),
            ActionAxes a => ApplyAxes(a),
            ActionArcMotion a => ApplyArc(a),
            ActionSpeed a => SetNonNegative(ref _speed, a.Relative ? Speed + a.Speed : a.Speed, "speed", "mm/s", strictlyPositive: true),
            ActionAcceleration a => SetNonNegative(ref _acceleration, a.Relative ? Acceleration + a.Acceleration : a.Acceleration, "acceleration", "mm/s^2", false),
            ActionPrecision a => SetNonNegative(ref _precision, a.Relative ? Precision + a.Precision : a.Precision, "precision", "mm", false),
            ActionExtrusionRate a => SetNonNegative(ref _extrusionRate, a.Relative ? ExtrusionRate + a.Rate : a.Rate, "extrusion rate", "mm/mm", false),
            ActionMotionMode a => Set(ref _motionType, a.MotionType),
            ActionCoordinates a => Set(ref _referenceCS, a.ReferenceCS),
            ActionPushPop a => a.Push ? PushSettings() : PopSettings(),
            ActionTemperature a => ApplyTemperature(a),
            ActionExtrusion a => Set(ref _isExtruding, a.Extrude),
            ActionExternalAxis a => ApplyExternalAxis(a),
            ActionArmAngle a => ApplyArmAngle(a),
            ActionDefineTool a => CheckTool(a) ?? DefineTool(a),
            ActionAttachTool a => AttachTool(a),
            ActionDetachTool a => DetachTool(a),
            ActionIODigital a => SetOutput(DigitalOutputs, a.IsToolPin, a.PinName, a.On),
            ActionIOAnalog a => CheckAnalog(a) ?? SetOutput(AnalogOutputs, a.IsToolPin, a.PinName, a.Value),
            ActionWait a => CheckWait(a),
            ActionWaitDigital a => CheckWaitDigital(a),
            ActionMessage or ActionComment or ActionCustomCode or ActionInitialization or ActionReadInput => null,
            _ => $"Machina does not know how to apply a {action.GetType().Name}.",
        };
    }

    /// <summary>The action being applied, so that warnings raised while applying it name it (not the previous one); null between actions.</summary>
    private RobotAction? _applying;

    private static string? Set<T>(ref T field, T value)
    {
        field = value;
        return null;
    }

    private static string? SetNonNegative(ref double field, double value, string what, string unit, bool strictlyPositive)
    {
        if (!double.IsFinite(value))
        {
            return $"the {what} would become too large to represent ({Num.G(field)} {unit} now).";
        }
        if (strictlyPositive ? !(value > 0) : !(value >= 0))
        {
            return $"the {what} would become {Num.G(value)} {unit}; it must be {(strictlyPositive ? "greater than 0" : "0 or more")}.";
        }
        if (BeyondSettingLimit(what, value, unit) is string beyond)
        {
            return beyond;
        }
        field = value;
        return null;
    }

    private string? PushSettings()
    {
        if (SettingsStack.Count >= MaxSettingsDepth)
        {
            return $"more than {MaxSettingsDepth} PushSettings without a PopSettings; is a PopSettings missing?";
        }
        SettingsStack.Push(CurrentSettings);
        return null;
    }

    private string? PopSettings()
    {
        if (SettingsStack.Count == 0)
        {
            return "there are no saved settings to restore; every PopSettings needs an earlier PushSettings.";
        }
        SettingsBeforeLastPop = CurrentSettings;
        ApplySettings(SettingsStack.Pop());
        return null;
    }

    private string? ApplyTemperature(ActionTemperature a)
    {
        int part = (int)a.Part;
        double value = a.Relative ? Temperatures[part] + a.Temperature : a.Temperature;
        if (!double.IsFinite(value))
        {
            return $"the {a.Part} temperature would become too large to represent ({Num.G(Temperatures[part])} C now).";
        }
        if (value < 0)
        {
            return $"the {a.Part} temperature would become {Num.G(value)} C; it cannot be below 0 C.";
        }
        if (BeyondSettingLimit($"{a.Part} temperature", value, "C") is string beyond)
        {
            return beyond;
        }
        Temperatures[part] = value;
        return null;
    }

    private string? ApplyExternalAxis(ActionExternalAxis a)
    {
        bool cartesian = a.Target != ExternalAxesTarget.Joint;
        bool joint = a.Target != ExternalAxesTarget.Cartesian;
        if (a.Relative)
        {
            if (cartesian && ExternalAxesCartesian?[a.AxisNumber] is null)
            {
                return $"cartesian external axis {a.AxisNumber} has no value yet to change; use ExternalAxisTo first.";
            }
            if (joint && ExternalAxesJoints?[a.AxisNumber] is null)
            {
                return $"joint external axis {a.AxisNumber} has no value yet to change; use ExternalAxisTo first.";
            }
        }
        double? newCartesian = cartesian ? NewAxisValue(ExternalAxesCartesian, a) : null;
        double? newJoint = joint ? NewAxisValue(ExternalAxesJoints, a) : null;
        foreach (double? value in (ReadOnlySpan<double?>)[newCartesian, newJoint])
        {
            if (value is double v && !double.IsFinite(v))
            {
                return $"external axis {a.AxisNumber} would become too large to represent.";
            }
            if (value >= ExternalAxes.Unset)
            {
                // ExternalAxes reads such values as "unset"; storing one would silently lose the axis.
                return $"external axis {a.AxisNumber} would become {Num.G(value.Value)}; values from {Num.G(ExternalAxes.Unset)} up mean \"no axis\" (ABB's 9E9).";
            }
        }
        if (newCartesian is double c)
        {
            ExternalAxesCartesian = (ExternalAxesCartesian ?? ExternalAxes.None).With(a.AxisNumber, c);
        }
        if (newJoint is double j)
        {
            ExternalAxesJoints = (ExternalAxesJoints ?? ExternalAxes.None).With(a.AxisNumber, j);
        }
        return null;
    }

    private static double NewAxisValue(ExternalAxes? set, ActionExternalAxis a) =>
        a.Relative ? set!.Value[a.AxisNumber]!.Value + a.Value : a.Value;

    private string? ApplyArmAngle(ActionArmAngle a)
    {
        if (a.Relative && ArmAngle is null)
        {
            return "the arm angle has no value yet to change; use ArmAngleTo first.";
        }
        if (a.Relative && !double.IsFinite(ArmAngle!.Value + a.Angle))
        {
            return $"the arm angle would become too large to represent ({Num.G(ArmAngle.Value)} degrees now).";
        }
        double angle = a.Relative ? ArmAngle!.Value + a.Angle : a.Angle;
        if (!Within(angle))
        {
            return $"the arm angle would become {Num.G(angle)} degrees; {JointLimitText}";
        }
        ArmAngle = angle;
        return null;
    }

    private static string? SetOutput<T>(Dictionary<string, T> outputs, bool toolPin, string pin, T value)
    {
        outputs[OutputKey(toolPin, pin)] = value;
        return null;
    }
}

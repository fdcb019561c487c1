namespace Machina.Tests.Support;

/// <summary>Compares robot states field by field, so that a refused action can be shown to have changed nothing.</summary>
internal static class StateAssert
{
    /// <summary>Pose, joints, settings, tool, stack depth, external axes, arm angle, temperatures, extrusion and last action are equal.</summary>
    internal static void Same(RobotState expected, RobotState actual)
    {
        Assert.Equal(expected.Position, actual.Position);
        Assert.Equal(expected.Rotation, actual.Rotation);
        Assert.Equal(expected.Axes, actual.Axes);
        Assert.Equal(expected.Settings, actual.Settings);
        Assert.Equal(expected.Tool, actual.Tool);
        Assert.Equal(expected.SettingsDepth, actual.SettingsDepth);
        Assert.Equal(expected.ArmAngle, actual.ArmAngle);
        Assert.Equal(expected.ExternalAxesCartesian, actual.ExternalAxesCartesian);
        Assert.Equal(expected.ExternalAxesJoints, actual.ExternalAxesJoints);
        Assert.Equal((expected.ExtruderTemperature, expected.BedTemperature, expected.ChamberTemperature),
            (actual.ExtruderTemperature, actual.BedTemperature, actual.ChamberTemperature));
        Assert.Equal(expected.ExtrudedLength, actual.ExtrudedLength);
        Assert.Equal(expected.LastAction, actual.LastAction);
    }
}

namespace Machina.Tests.Online;

/// <summary>
/// What each driver refuses online is only what its controller cannot do (issue 46, docs/online.md "What cannot be streamed"):
/// arcs stream to UR and KUKA, Coordinates on UR and Initialize/Terminate on KUKA send nothing, the rest is refused with its reason.
/// </summary>
public class OnlineVerbCoverageTests
{
    private static readonly Plane Through = new(new Vector(10, 10, 0), Rotation.Identity), To = new(new Vector(20, 0, 0), Rotation.Identity);

    [Fact]
    public void WhyCannotStream_ArcsAndStateOnlyVerbs_Accepted()
    {
        var ur = new UrOnline();
        var kuka = new KukaOnline();
        Assert.Null(ur.WhyCannotStream(new ActionArcMotion(Through, To, true, true)));
        Assert.Null(kuka.WhyCannotStream(new ActionArcMotion(Through, To, true, true)));
        Assert.Null(ur.WhyCannotStream(new ActionCoordinates(ReferenceCS.Local)));
        Assert.Null(kuka.WhyCannotStream(new ActionInitialization(true)));
        Assert.Null(kuka.WhyCannotStream(new ActionInitialization(false)));
    }

    [Fact]
    public void Encode_StateOnlyVerbs_SendNothing()
    {
        var cursor = new RobotCursor();
        RobotAction coordinates = new ActionCoordinates(ReferenceCS.Local) { Id = 1 }, start = new ActionInitialization(true) { Id = 2 };
        Assert.Null(cursor.TryApply(coordinates));
        Assert.Null(cursor.TryApply(start));
        Assert.Equal(0, UrActionEncoder.Encode(coordinates, cursor, new int[UrActionEncoder.MaxValues]));
        Assert.Null(KukaActionEncoder.Encode(start, 2, cursor));
    }

    public static TheoryData<RobotAction, string> UrRefused => new()
    {
        { new ActionExternalAxis(1, 100, ExternalAxesTarget.All, false), "a UR arm has six joints and no external axes to move." },
        { new ActionArmAngle(10, false), "UR arms have six joints and no arm angle" },
        { new ActionCustomCode("textmsg(1)", false), "the driver cannot run URScript text sent while it runs: URScript has no eval" },
        { new ActionTemperature(200, RobotPartType.Extruder, false, false), "a UR robot has no heaters to control." },
        { new ActionExtrusion(true), "a UR robot has no extruder" },
        { new ActionExtrusionRate(10, false), "a UR robot has no extruder" },
    };

    [Theory]
    [MemberData(nameof(UrRefused))]
    public void WhyCannotStream_Ur_WhatAUrCannotDo_RefusedWithTheReason(RobotAction action, string reason)
    {
        string? why = new UrOnline().WhyCannotStream(action);
        Assert.NotNull(why);
        Assert.StartsWith($"\"{action}\" cannot be streamed to a UR robot: ", why, StringComparison.Ordinal);
        Assert.Contains(reason, why, StringComparison.Ordinal);
    }
}

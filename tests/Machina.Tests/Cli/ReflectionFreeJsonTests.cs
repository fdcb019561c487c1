using System.Text;
using System.Text.Json;
using Machina.Bridge;
using Machina.Cli.Preview;

namespace Machina.Tests.Cli;

/// <summary>
/// The JSON the native tool writes by hand (no reflection, so it trims) is byte for byte what System.Text.Json's reflection
/// serializer wrote before: the preview's path data and the bridge page's WebSocket path.
/// </summary>
public sealed class ReflectionFreeJsonTests
{
    [Fact]
    public void PreviewJson_IsWhatTheSerializerWrote()
    {
        var path = new PreviewPath();
        path.Targets.Add(new Vector(0.1 + 0.2, -1e-7, 1234.56789));
        path.Targets.Add(new Vector(300, 1.0 / 3, -0.0004));
        path.Segments.Add(new PathSegment(SegmentKind.Linear, 3, [new Vector(0.1 + 0.2, -1e-7, 1234.56789), new Vector(300, 1.0 / 3, -0.0004)]));
        path.Segments.Add(new PathSegment(SegmentKind.Arc, 4, [new Vector(1e21, 2.5, 0), new Vector(-7, 8, 9)]));
        path.Warnings.Add(new PathWarning(null, 5, 1, "Move(1, 2, 3);", "not applied: <the arm & \"its\" reach> é"));
        path.Warnings.Add(new PathWarning(new Vector(1, 2, 3), 6, 2, "Rotate(0, 0, 1, 90);", "a kinematic issue"));
        path.Arms.Add(new ArmPose("start", [Vector.Zero, new Vector(0, 0, 290), new Vector(374.0004, 1.0 / 3, 630)]));

        string expected = JsonSerializer.Serialize(OldDocument(path));

        Assert.Equal(expected, HtmlWriter.Json(path));
        Assert.Contains("\\u003Cthe arm \\u0026 \\u0022its\\u0022 reach\\u003E \\u00E9", expected, StringComparison.Ordinal);
    }

    [Fact]
    public void PreviewJson_OfAnEmptyPath_HasNullEnds()
    {
        var path = new PreviewPath();

        Assert.Equal(JsonSerializer.Serialize(OldDocument(path)), HtmlWriter.Json(path));
        Assert.StartsWith("{\"units\":\"mm\",\"segments\":[],\"targets\":[],\"start\":null,\"end\":null,\"warnings\":[],\"arms\":[],\"reach\":[],\"colours\":{", HtmlWriter.Json(path), StringComparison.Ordinal);
    }

    [Theory]
    [InlineData("/")]
    [InlineData("/ws")]
    [InlineData("/a</script><b>&\"c\"'é")]
    public void BridgePage_SocketPathLiteral_IsWhatTheSerializerWrote(string socketPath)
    {
        string page = Encoding.UTF8.GetString(BridgePage.Render(socketPath));

        Assert.Contains(JsonSerializer.Serialize(socketPath), page, StringComparison.Ordinal);
        Assert.DoesNotContain("\"__BRIDGE_PATH__\"", page, StringComparison.Ordinal);
    }

    /// <summary>The anonymous document the preview used to hand to JsonSerializer (kept here as the reference).</summary>
    private static object OldDocument(PreviewPath path)
    {
        static double[] A(Vector v) => [Math.Round(v.X, 3), Math.Round(v.Y, 3), Math.Round(v.Z, 3)];
        var colours = PreviewStyle.Kinds.ToDictionary(k => PreviewStyle.Of(k).Name, k => PreviewStyle.Of(k).Colour);
        colours["start"] = PreviewStyle.StartColour;
        colours["end"] = PreviewStyle.EndColour;
        colours["warning"] = PreviewStyle.WarningColour;
        colours["arm-start"] = PreviewStyle.ArmStartColour;
        colours["arm-end"] = PreviewStyle.ArmEndColour;
        colours["arm-warning"] = PreviewStyle.ArmWarningColour;
        colours["reach"] = PreviewStyle.ReachColour;
        return new
        {
            units = "mm",
            segments = path.Segments.Select(s => new { kind = PreviewStyle.Of(s.Kind).Name, line = s.Line, points = s.Points.Select(A).ToArray() }),
            targets = path.Targets.Select(A),
            start = path.Start is Vector s0 ? A(s0) : null,
            end = path.End is Vector e0 ? A(e0) : null,
            warnings = path.Warnings.Select(w => new { at = w.At is Vector at ? A(at) : null, line = w.Line, instruction = w.Instruction, message = w.Message }),
            arms = path.Arms.Select(a => new { label = a.Label, points = a.Points.Select(A) }),
            reach = (path.Reach is ReachEnvelope r ? new[] { r.InPlane(0), r.InPlane(90), r.Circle(r.RadiusHeight) } : []).Select(o => new { points = o.Select(A) }),
            colours,
        };
    }
}

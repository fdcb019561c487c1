using System.Buffers;
using System.Globalization;
using System.Security;
using System.Text;
using System.Text.Json;

namespace Machina.Cli.Preview;

/// <summary>
/// Writes a tool path as one self-contained HTML page with an interactive 3D view (a canvas and a small script, no network):
/// the path data sits in a JSON block (<c>&lt;script type="application/json" id="machina-path"&gt;</c>) in millimetres.
/// </summary>
internal static class HtmlWriter
{
    /// <summary>The HTML text of <paramref name="path"/>.</summary>
    internal static string Write(PreviewPath path, string title, string subtitle)
    {
        var html = new StringBuilder();
        html.Append("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n");
        html.Append("<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n");
        html.Append(CultureInfo.InvariantCulture, $"<title>{Esc(title)}</title>\n");
        html.Append("""
            <style>
            html,body{margin:0;height:100%;font-family:"Segoe UI",Helvetica,Arial,sans-serif;color:#2b2f36;background:#f6f7f9}
            #app{display:flex;height:100%}
            #stage{flex:1;position:relative;min-width:200px;margin:12px;border:1px solid #d0d4da;border-radius:6px;overflow:hidden;background:#fff}
            #view{display:block;cursor:grab}
            #tip{position:absolute;display:none;background:#2b2f36;color:#fff;font-size:12px;padding:4px 7px;border-radius:4px;pointer-events:none;max-width:420px}
            #side{width:320px;padding:16px 16px 16px 4px;overflow:auto;font-size:13px}
            h1{font-size:18px;margin:0 0 2px}
            .sub{color:#5f6b7a;margin:0 0 12px}
            button{font:inherit;padding:4px 10px;margin:0 4px 4px 0;border:1px solid #c3c8d0;background:#fff;border-radius:4px;cursor:pointer}
            button:hover{background:#eef1f5}
            .key{display:flex;align-items:center;margin:5px 0}
            .swatch{width:34px;height:0;border-top:3px solid;margin-right:9px}
            .dot{width:12px;height:12px;border-radius:50%;margin:0 20px 0 11px}
            .none{color:#9aa2ad}
            .warn{color:#c62828;margin:6px 0;word-wrap:break-word}
            .help{color:#5f6b7a;font-size:12px;margin-top:14px}
            </style>
            </head>
            <body>
            <div id="app">
            <div id="stage"><canvas id="view"></canvas><div id="tip"></div></div>
            <div id="side">

            """);
        html.Append(CultureInfo.InvariantCulture, $"<h1>{Esc(title)}</h1>\n<p class=\"sub\">{Esc(subtitle)}</p>\n");
        html.Append("<div><button id=\"v-3d\">3D</button><button id=\"v-top\">Top</button><button id=\"v-front\">Front</button><button id=\"v-side\">Side</button></div>\n");
        html.Append("<h3>Legend</h3>\n");
        var present = path.Segments.Select(s => s.Kind).ToHashSet();
        foreach (SegmentKind kind in PreviewStyle.Kinds)
        {
            (string name, string colour, _) = PreviewStyle.Of(kind);
            string label = PreviewStyle.Label(kind, path);
            string style = kind == SegmentKind.Joint ? "dashed" : kind == SegmentKind.Travel ? "dotted" : "solid";
            int count = path.Segments.Count(s => s.Kind == kind);
            html.Append(CultureInfo.InvariantCulture,
                $"<div class=\"key{(present.Contains(kind) ? "" : " none")}\"><span class=\"swatch\" style=\"border-top-color:{colour};border-top-style:{style}\"></span>{Esc(label)} ({(count == 0 ? "none" : count.ToString(CultureInfo.InvariantCulture))})</div>\n");
        }
        html.Append(CultureInfo.InvariantCulture, $"<div class=\"key\"><span class=\"dot\" style=\"background:{PreviewStyle.StartColour}\"></span>start {P(path.Start)}</div>\n");
        html.Append(CultureInfo.InvariantCulture, $"<div class=\"key\"><span class=\"dot\" style=\"background:{PreviewStyle.EndColour};border-radius:0\"></span>end {P(path.End)}</div>\n");
        html.Append(CultureInfo.InvariantCulture, $"<div class=\"key\"><span class=\"dot\" style=\"border:2px solid {PreviewStyle.WarningColour};width:9px;height:9px\"></span>warning, with its line ({path.Warnings.Count})</div>\n");
        if (path.Arms.Count > 0)
        {
            html.Append(CultureInfo.InvariantCulture, $"<div class=\"key\"><span class=\"dot\" style=\"background:{PreviewStyle.ArmStartColour};border-radius:2px;width:22px;height:6px\"></span>the arm at the start (light) and the end (dark), base at 0,0,0</div>\n");
        }
        if (path.Reach is ReachEnvelope reach)
        {
            html.Append(CultureInfo.InvariantCulture, $"<div class=\"key\"><span class=\"swatch\" style=\"border-top-color:{PreviewStyle.ReachColour};border-top-style:dashed\"></span>reach: the flange cannot get beyond these lines (up to {reach.Radius.ToString("0", CultureInfo.InvariantCulture)} mm out)</div>\n");
        }
        html.Append("<p id=\"grid\" class=\"help\"></p>\n");
        if (path.Warnings.Count > 0)
        {
            html.Append("<h3>Warnings</h3>\n");
            foreach (PathWarning warning in path.Warnings.Take(200))
            {
                html.Append(CultureInfo.InvariantCulture, $"<div class=\"warn\">line {warning.Line}: {Esc(warning.Instruction)} {Esc(warning.Message)}</div>\n");
            }
            if (path.Warnings.Count > 200)
            {
                html.Append(CultureInfo.InvariantCulture, $"<div class=\"warn\">… and {path.Warnings.Count - 200} more</div>\n");
            }
        }
        html.Append("<p class=\"help\">Drag to turn the view, Shift+drag or right-drag to move it, scroll to zoom. Point at a target or a warning to read it. Units: mm.</p>\n");
        html.Append("</div>\n</div>\n");
        html.Append("<script type=\"application/json\" id=\"machina-path\">").Append(Json(path)).Append("</script>\n");
        html.Append("<script>\n").Append(Script.Value).Append("</script>\n</body>\n</html>\n");
        return html.ToString();
    }

    /// <summary>The path as JSON: segments (kind, line, points), targets, start, end, warnings, arms (label, joints) and colours; coordinates in mm.</summary>
    internal static string Json(PreviewPath path)
    {
        var colours = PreviewStyle.Kinds.ToDictionary(k => PreviewStyle.Of(k).Name, k => PreviewStyle.Of(k).Colour);
        colours["start"] = PreviewStyle.StartColour;
        colours["end"] = PreviewStyle.EndColour;
        colours["warning"] = PreviewStyle.WarningColour;
        colours["arm-start"] = PreviewStyle.ArmStartColour;
        colours["arm-end"] = PreviewStyle.ArmEndColour;
        colours["arm-warning"] = PreviewStyle.ArmWarningColour;
        colours["reach"] = PreviewStyle.ReachColour;
        // Written by hand (no reflection, so the native tool can trim it), in the order and form the serializer used;
        // the default encoder escapes <, > and &, so the JSON cannot close its script element.
        var buffer = new ArrayBufferWriter<byte>(4096);
        using (var w = new Utf8JsonWriter(buffer))
        {
            w.WriteStartObject();
            w.WriteString("units", "mm");
            w.WriteStartArray("segments");
            foreach (PathSegment segment in path.Segments)
            {
                w.WriteStartObject();
                w.WriteString("kind", PreviewStyle.Of(segment.Kind).Name);
                w.WriteNumber("line", segment.Line);
                Points(w, segment.Points);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("targets");
            foreach (Vector target in path.Targets)
            {
                Point(w, target);
            }
            w.WriteEndArray();
            w.WritePropertyName("start");
            Point(w, path.Start);
            w.WritePropertyName("end");
            Point(w, path.End);
            w.WriteStartArray("warnings");
            foreach (PathWarning warning in path.Warnings)
            {
                w.WriteStartObject();
                w.WritePropertyName("at");
                Point(w, warning.At);
                w.WriteNumber("line", warning.Line);
                w.WriteString("instruction", warning.Instruction);
                w.WriteString("message", warning.Message);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("arms");
            foreach (ArmPose arm in path.Arms)
            {
                w.WriteStartObject();
                w.WriteString("label", arm.Label);
                Points(w, arm.Points);
                w.WriteEndObject();
            }
            w.WriteEndArray();
            w.WriteStartArray("reach");
            if (path.Reach is ReachEnvelope reach)
            {
                foreach (IReadOnlyList<Vector> outline in new[] { reach.InPlane(0), reach.InPlane(90), reach.Circle(reach.RadiusHeight) })
                {
                    w.WriteStartObject();
                    Points(w, outline);
                    w.WriteEndObject();
                }
            }
            w.WriteEndArray();
            w.WriteStartObject("colours");
            foreach (KeyValuePair<string, string> colour in colours)
            {
                w.WriteString(colour.Key, colour.Value);
            }
            w.WriteEndObject();
            w.WriteEndObject();
        }
        return Encoding.UTF8.GetString(buffer.WrittenSpan);
    }

    /// <summary>A <c>points</c> property: the points in order, each as <see cref="Point"/> writes it.</summary>
    private static void Points(Utf8JsonWriter w, IReadOnlyList<Vector> points)
    {
        w.WriteStartArray("points");
        foreach (Vector point in points)
        {
            Point(w, point);
        }
        w.WriteEndArray();
    }

    /// <summary>One point as <c>[x,y,z]</c> rounded to 0.001 mm, or <c>null</c> when there is none.</summary>
    private static void Point(Utf8JsonWriter w, Vector? point)
    {
        if (point is not Vector v)
        {
            w.WriteNullValue();
            return;
        }
        w.WriteStartArray();
        w.WriteNumberValue(Math.Round(v.X, 3));
        w.WriteNumberValue(Math.Round(v.Y, 3));
        w.WriteNumberValue(Math.Round(v.Z, 3));
        w.WriteEndArray();
    }

    private static readonly Lazy<string> Script = new(() =>
    {
        using Stream stream = typeof(HtmlWriter).Assembly.GetManifestResourceStream("Machina.Cli.Preview.preview3d.js")
            ?? throw new InvalidOperationException("The 3D view script is missing from the machina tool.");
        using var reader = new StreamReader(stream);
        return reader.ReadToEnd();
    });

    private static string P(Vector? p) => p is Vector v
        ? string.Create(CultureInfo.InvariantCulture, $"[{v.X:0.##}, {v.Y:0.##}, {v.Z:0.##}] mm")
        : "unknown";

    private static string Esc(string text) => SecurityElement.Escape(text);
}

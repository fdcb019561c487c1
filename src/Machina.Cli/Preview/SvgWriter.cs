using System.Globalization;
using System.Security;
using System.Text;

namespace Machina.Cli.Preview;

/// <summary>
/// Draws a tool path as one SVG picture with three views, as on an engineering drawing: top (X right, Y up), front (X right,
/// Z up) and side (Y right, Z up), all at the same scale, with a grid, a scale bar, a legend and the warnings. Each view's
/// drawing is in a group whose transform maps millimetres to the picture, so the points in the file are the program's own.
/// </summary>
internal static class SvgWriter
{
    private const double Width = 1200, Height = 900, Gap = 20, TitleHeight = 50, PanelPad = 34;
    private const int MaxListedWarnings = 12;

    private sealed record View(string Name, string Title, string Horizontal, string Vertical, Func<Vector, (double U, double V)> Project);

    private static readonly View[] Views =
    [
        new("top", "Top view", "X", "Y", p => (p.X, p.Y)),
        new("front", "Front view", "X", "Z", p => (p.X, p.Z)),
        new("side", "Side view", "Y", "Z", p => (p.Y, p.Z)),
    ];

    /// <summary>The SVG text of <paramref name="path"/>, titled <paramref name="title"/>.</summary>
    internal static string Write(PreviewPath path, string title, string subtitle)
    {
        var svg = new StringBuilder();
        svg.Append(CultureInfo.InvariantCulture, $"<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{Width}\" height=\"{Height}\" viewBox=\"0 0 {Width} {Height}\" font-family=\"Segoe UI, Helvetica, Arial, sans-serif\">\n");
        svg.Append("<style>\n");
        svg.Append(".panel{fill:#fff;stroke:#d0d4da}.grid{stroke:#eceff3;stroke-width:1;vector-effect:non-scaling-stroke}");
        svg.Append(".axis{stroke:#b8bec8;stroke-width:1;vector-effect:non-scaling-stroke}");
        svg.Append(".seg{fill:none;stroke-width:2.2;stroke-linejoin:round;stroke-linecap:round;vector-effect:non-scaling-stroke}");
        foreach (SegmentKind kind in PreviewStyle.Kinds)
        {
            (string name, string colour, _) = PreviewStyle.Of(kind);
            svg.Append(CultureInfo.InvariantCulture, $".{name}{{stroke:{colour}}}");
        }
        svg.Append(".joint{stroke-dasharray:7 5}.travel{stroke-dasharray:2 5;stroke-width:1.5}");
        svg.Append(".arm{fill:none;stroke-width:7;stroke-linejoin:round;stroke-linecap:round;vector-effect:non-scaling-stroke;opacity:.75}");
        svg.Append(CultureInfo.InvariantCulture, $".arm-start{{stroke:{PreviewStyle.ArmStartColour}}}.arm-end{{stroke:{PreviewStyle.ArmEndColour}}}.arm-warning{{stroke:{PreviewStyle.ArmWarningColour}}}");
        svg.Append(CultureInfo.InvariantCulture, $".reach{{fill:none;stroke:{PreviewStyle.ReachColour};stroke-width:1.3;stroke-dasharray:9 4 2 4;vector-effect:non-scaling-stroke}}");
        svg.Append(".arm-joint{fill:#fff;stroke:#6b7684;stroke-width:1.2;vector-effect:non-scaling-stroke}");
        svg.Append(".target{fill:#fff;stroke:#5f6b7a;stroke-width:1;vector-effect:non-scaling-stroke}");
        // A text's own fill (a label in its marker's colour) wins over the default: a CSS rule would override the attribute.
        svg.Append("text{font-size:13px}text:not([fill]){fill:#2b2f36}.title{font-size:20px;font-weight:600}.sub{fill:#5f6b7a}.small{font-size:11px;fill:#5f6b7a}");
        svg.Append("\n</style>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<rect width=\"{Width}\" height=\"{Height}\" fill=\"#f6f7f9\"/>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{Gap}\" y=\"30\" class=\"title\">{Esc(title)}</text>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{Gap}\" y=\"47\" class=\"sub\">{Esc(subtitle)}</text>\n");

        double panelW = (Width - (3 * Gap)) / 2, panelH = (Height - TitleHeight - (3 * Gap)) / 2;
        (double X, double Y)[] origins =
        [
            (Gap, TitleHeight + Gap),
            (Gap, TitleHeight + (2 * Gap) + panelH),
            (2 * Gap + panelW, TitleHeight + (2 * Gap) + panelH),
        ];
        (Vector min, Vector max) = path.Bounds() ?? (new Vector(-50, -50, -50), new Vector(50, 50, 50));
        // One scale for the three views, so that the same length looks the same everywhere.
        double plotW = panelW - (2 * PanelPad), plotH = panelH - (2 * PanelPad) - 10;
        double Span(double a, double b) => Math.Max(b - a, 1) * 1.08;
        double scale = new[]
        {
            plotW / Span(min.X, max.X), plotH / Span(min.Y, max.Y), plotH / Span(min.Z, max.Z), plotW / Span(min.Y, max.Y),
        }.Min();
        for (int i = 0; i < Views.Length; i++)
        {
            WriteView(svg, path, Views[i], origins[i].X, origins[i].Y, panelW, panelH, scale, min, max);
        }
        WriteLegend(svg, path, 2 * Gap + panelW, TitleHeight + Gap, panelW, panelH, min, max);
        svg.Append("</svg>\n");
        return svg.ToString();
    }

    private static void WriteView(StringBuilder svg, PreviewPath path, View view, double x, double y, double w, double h, double scale, Vector min, Vector max)
    {
        (double u0, double v0) = view.Project(min);
        (double u1, double v1) = view.Project(max);
        double mu = (u0 + u1) / 2, mv = (v0 + v1) / 2;
        double cx = x + (w / 2), cy = y + 22 + ((h - 22) / 2);
        (double X, double Y) Screen(Vector p)
        {
            (double u, double v) = view.Project(p);
            return (cx + (scale * (u - mu)), cy - (scale * (v - mv)));
        }
        svg.Append(CultureInfo.InvariantCulture, $"<g id=\"view-{view.Name}\">\n");
        svg.Append(CultureInfo.InvariantCulture, $"<rect class=\"panel\" x=\"{F(x)}\" y=\"{F(y)}\" width=\"{F(w)}\" height=\"{F(h)}\" rx=\"6\"/>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 12)}\" y=\"{F(y + 20)}\" font-weight=\"600\">{view.Title}</text>");
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 100)}\" y=\"{F(y + 20)}\" class=\"small\">{view.Horizontal} to the right, {view.Vertical} up (mm)</text>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<clipPath id=\"clip-{view.Name}\"><rect x=\"{F(x + 1)}\" y=\"{F(y + 26)}\" width=\"{F(w - 2)}\" height=\"{F(h - 27)}\"/></clipPath>\n");
        svg.Append(CultureInfo.InvariantCulture, $"<g clip-path=\"url(#clip-{view.Name})\">\n");
        // The drawing itself, in millimetres: screen = (cx, cy) + scale · (u − mu, −(v − mv)).
        svg.Append(CultureInfo.InvariantCulture,
            $"<g class=\"view\" data-view=\"{view.Name}\" data-axes=\"{view.Horizontal}{view.Vertical}\" transform=\"translate({F(cx)} {F(cy)}) scale({F6(scale)} {F6(-scale)}) translate({F(-mu)} {F(-mv)})\">\n");
        double step = NiceStep(Math.Max(w, h) / scale / 10);
        double halfU = w / 2 / scale, halfV = h / 2 / scale;
        svg.Append("<g class=\"grid-lines\">");
        for (double u = Math.Ceiling((mu - halfU) / step) * step; u <= mu + halfU; u += step)
        {
            svg.Append(CultureInfo.InvariantCulture, $"<line class=\"{(Math.Abs(u) < step / 1000 ? "axis" : "grid")}\" x1=\"{F(u)}\" y1=\"{F(mv - halfV)}\" x2=\"{F(u)}\" y2=\"{F(mv + halfV)}\"/>");
        }
        for (double v = Math.Ceiling((mv - halfV) / step) * step; v <= mv + halfV; v += step)
        {
            svg.Append(CultureInfo.InvariantCulture, $"<line class=\"{(Math.Abs(v) < step / 1000 ? "axis" : "grid")}\" x1=\"{F(mu - halfU)}\" y1=\"{F(v)}\" x2=\"{F(mu + halfU)}\" y2=\"{F(v)}\"/>");
        }
        svg.Append("</g>\n");
        WriteReach(svg, path, view);
        WriteArms(svg, path, view, scale);
        foreach ((SegmentKind kind, List<Vector> points) in Runs(path.Segments))
        {
            (string name, _, _) = PreviewStyle.Of(kind);
            svg.Append(CultureInfo.InvariantCulture, $"<polyline class=\"seg {name}\" data-kind=\"{name}\" points=\"");
            for (int i = 0; i < points.Count; i++)
            {
                (double u, double v) = view.Project(points[i]);
                svg.Append(i == 0 ? "" : " ").Append(F(u)).Append(',').Append(F(v));
            }
            svg.Append("\"/>\n");
        }
        svg.Append("<g class=\"targets\">");
        double r = 2.6 / scale;
        foreach (Vector p in path.Targets)
        {
            (double u, double v) = view.Project(p);
            svg.Append(CultureInfo.InvariantCulture, $"<circle class=\"target\" cx=\"{F(u)}\" cy=\"{F(v)}\" r=\"{F6(r)}\"/>");
        }
        svg.Append("</g>\n</g>\n");
        // Markers in picture coordinates, so that their size and labels do not depend on the scale; no two labels overlap.
        var labels = new LabelPlacer();
        foreach (PathWarning warning in path.Warnings)
        {
            if (warning.At is Vector at)
            {
                (double sx, double sy) = Screen(at);
                labels.AddMarker(sx, sy, 8, 8);
            }
        }
        (double X, double Y)? baseAt = path.Arms.Count > 0 ? Screen(Vector.Zero) : null;
        (double X, double Y)? startAt = path.Start is Vector s0 ? Screen(s0) : null;
        (double X, double Y)? endAt = path.End is Vector e0 ? Screen(e0) : null;
        if (baseAt is { } b)
        {
            labels.AddMarker(b.X, b.Y, 9, 4);
        }
        if (startAt is { } st)
        {
            labels.AddMarker(st.X, st.Y, 7.5, 7.5);
        }
        if (endAt is { } en)
        {
            labels.AddMarker(en.X, en.Y, 6.5, 6.5);
        }
        LabelSpot? startLabel = startAt is { } sl ? labels.Place(sl.X, sl.Y, "start", 12, LabelCorner.BelowRight) : null;
        LabelSpot? endLabel = endAt is { } el ? labels.Place(el.X, el.Y, "end", 12, LabelCorner.AboveRight) : null;
        foreach (PathWarning warning in path.Warnings)
        {
            if (warning.At is Vector at)
            {
                (double sx, double sy) = Screen(at);
                string text = $"!{warning.Line}";
                LabelSpot spot = labels.Place(sx, sy, text, 11, LabelCorner.AboveLeft);
                svg.Append(CultureInfo.InvariantCulture,
                    $"<g class=\"warning\"><title>line {warning.Line}: {Esc(warning.Instruction)} {Esc(warning.Message)}</title>" +
                    $"<circle cx=\"{F(sx)}\" cy=\"{F(sy)}\" r=\"7\" fill=\"none\" stroke=\"{PreviewStyle.WarningColour}\" stroke-width=\"2.5\"/>" +
                    $"<text x=\"{F(spot.X)}\" y=\"{F(spot.Y)}\" text-anchor=\"{spot.Anchor}\" fill=\"{PreviewStyle.WarningColour}\" font-size=\"11\" font-weight=\"700\">{text}</text></g>\n");
            }
        }
        if (baseAt is { } bx0)
        {
            LabelSpot spot = labels.Place(bx0.X, bx0.Y, "base", 11, LabelCorner.Below);
            svg.Append(CultureInfo.InvariantCulture, $"<g class=\"base\"><rect x=\"{F(bx0.X - 9)}\" y=\"{F(bx0.Y - 4)}\" width=\"18\" height=\"8\" rx=\"2\" fill=\"#5f6b7a\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(spot.X)}\" y=\"{F(spot.Y)}\" text-anchor=\"{spot.Anchor}\" class=\"small\">base</text></g>\n");
        }
        if (startAt is { } sa && startLabel is { } ss)
        {
            svg.Append(CultureInfo.InvariantCulture, $"<g class=\"start\"><circle cx=\"{F(sa.X)}\" cy=\"{F(sa.Y)}\" r=\"6.5\" fill=\"{PreviewStyle.StartColour}\" stroke=\"#fff\" stroke-width=\"2\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(ss.X)}\" y=\"{F(ss.Y)}\" text-anchor=\"{ss.Anchor}\" fill=\"{PreviewStyle.StartColour}\" font-size=\"12\" font-weight=\"700\">start</text></g>\n");
        }
        if (endAt is { } ea && endLabel is { } es)
        {
            svg.Append(CultureInfo.InvariantCulture, $"<g class=\"end\"><rect x=\"{F(ea.X - 5.5)}\" y=\"{F(ea.Y - 5.5)}\" width=\"11\" height=\"11\" fill=\"{PreviewStyle.EndColour}\" stroke=\"#fff\" stroke-width=\"2\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(es.X)}\" y=\"{F(es.Y)}\" text-anchor=\"{es.Anchor}\" fill=\"{PreviewStyle.EndColour}\" font-size=\"12\" font-weight=\"700\">end</text></g>\n");
        }
        svg.Append("</g>\n");
        // Scale bar, bottom left.
        double barPx = step * scale;
        double bx = x + 14, by = y + h - 14;
        svg.Append(CultureInfo.InvariantCulture, $"<g class=\"scale-bar\"><line x1=\"{F(bx)}\" y1=\"{F(by)}\" x2=\"{F(bx + barPx)}\" y2=\"{F(by)}\" stroke=\"#2b2f36\" stroke-width=\"2\"/>");
        svg.Append(CultureInfo.InvariantCulture, $"<line x1=\"{F(bx)}\" y1=\"{F(by - 4)}\" x2=\"{F(bx)}\" y2=\"{F(by + 1)}\" stroke=\"#2b2f36\" stroke-width=\"2\"/><line x1=\"{F(bx + barPx)}\" y1=\"{F(by - 4)}\" x2=\"{F(bx + barPx)}\" y2=\"{F(by + 1)}\" stroke=\"#2b2f36\" stroke-width=\"2\"/>");
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(bx + barPx + 6)}\" y=\"{F(by + 4)}\" class=\"small\">{G(step)} mm (grid)</text></g>\n");
        svg.Append("</g>\n");
    }

    /// <summary>The reach envelope's outline as this view sees it (in millimetres, inside the view's transform): a circle from above, the outline from the front or the side.</summary>
    private static void WriteReach(StringBuilder svg, PreviewPath path, View view)
    {
        if (path.Reach is not ReachEnvelope reach)
        {
            return;
        }
        IReadOnlyList<Vector> points = view.Name switch
        {
            "top" => reach.Circle(reach.RadiusHeight),
            "front" => reach.InPlane(0),
            _ => reach.InPlane(90),
        };
        svg.Append(CultureInfo.InvariantCulture, $"<polyline class=\"reach\" data-reach=\"{view.Name}\" points=\"");
        for (int i = 0; i < points.Count; i++)
        {
            (double u, double v) = view.Project(points[i]);
            svg.Append(i == 0 ? "" : " ").Append(F(u)).Append(',').Append(F(v));
        }
        svg.Append("\"/>\n");
    }

    /// <summary>The arm at its drawn moments, in millimetres (inside the view's transform): a thick grey line through its joints.</summary>
    private static void WriteArms(StringBuilder svg, PreviewPath path, View view, double scale)
    {
        if (path.Arms.Count == 0)
        {
            return;
        }
        svg.Append("<g class=\"arms\">");
        double r = 3.2 / scale;
        foreach (ArmPose arm in path.Arms)
        {
            string kind = arm.Label is "start" or "end" ? arm.Label : "warning";
            svg.Append(CultureInfo.InvariantCulture, $"<polyline class=\"arm arm-{kind}\" data-arm=\"{Esc(arm.Label)}\" points=\"");
            for (int i = 0; i < arm.Points.Count; i++)
            {
                (double u, double v) = view.Project(arm.Points[i]);
                svg.Append(i == 0 ? "" : " ").Append(F(u)).Append(',').Append(F(v));
            }
            svg.Append("\"/>");
            foreach (Vector joint in arm.Points)
            {
                (double u, double v) = view.Project(joint);
                svg.Append(CultureInfo.InvariantCulture, $"<circle class=\"arm-joint\" cx=\"{F(u)}\" cy=\"{F(v)}\" r=\"{F6(r)}\"/>");
            }
        }
        svg.Append("</g>\n");
    }

    private static void WriteLegend(StringBuilder svg, PreviewPath path, double x, double y, double w, double h, Vector min, Vector max)
    {
        svg.Append("<g id=\"legend\">\n");
        svg.Append(CultureInfo.InvariantCulture, $"<rect class=\"panel\" x=\"{F(x)}\" y=\"{F(y)}\" width=\"{F(w)}\" height=\"{F(h)}\" rx=\"6\"/>\n");
        double ty = y + 24;
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 14)}\" y=\"{F(ty)}\" font-weight=\"600\">Legend</text>\n");
        var present = path.Segments.Select(s => s.Kind).ToHashSet();
        foreach (SegmentKind kind in PreviewStyle.Kinds)
        {
            ty += 21;
            (string name, string colour, _) = PreviewStyle.Of(kind);
            string label = PreviewStyle.Label(kind, path);
            string dash = kind == SegmentKind.Joint ? " stroke-dasharray=\"7 5\"" : kind == SegmentKind.Travel ? " stroke-dasharray=\"2 5\"" : "";
            string count = present.Contains(kind) ? $"  ({path.Segments.Count(s => s.Kind == kind)})" : "  (none)";
            svg.Append(CultureInfo.InvariantCulture, $"<line x1=\"{F(x + 16)}\" y1=\"{F(ty - 4)}\" x2=\"{F(x + 52)}\" y2=\"{F(ty - 4)}\" stroke=\"{colour}\" stroke-width=\"3\"{dash}/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 62)}\" y=\"{F(ty)}\"{(present.Contains(kind) ? "" : " class=\"small\"")}>{Esc(label)}{count}</text>\n");
        }
        ty += 24;
        svg.Append(CultureInfo.InvariantCulture, $"<circle cx=\"{F(x + 24)}\" cy=\"{F(ty - 4)}\" r=\"6\" fill=\"{PreviewStyle.StartColour}\"/><text x=\"{F(x + 40)}\" y=\"{F(ty)}\">start {P(path.Start)}</text>\n");
        ty += 21;
        svg.Append(CultureInfo.InvariantCulture, $"<rect x=\"{F(x + 19)}\" y=\"{F(ty - 9.5)}\" width=\"11\" height=\"11\" fill=\"{PreviewStyle.EndColour}\"/><text x=\"{F(x + 40)}\" y=\"{F(ty)}\">end {P(path.End)}</text>\n");
        ty += 21;
        svg.Append(CultureInfo.InvariantCulture, $"<circle cx=\"{F(x + 24)}\" cy=\"{F(ty - 4)}\" r=\"3\" fill=\"#fff\" stroke=\"#5f6b7a\"/><text x=\"{F(x + 40)}\" y=\"{F(ty)}\">target ({path.Targets.Count})</text>\n");
        ty += 21;
        svg.Append(CultureInfo.InvariantCulture, $"<circle cx=\"{F(x + 24)}\" cy=\"{F(ty - 4)}\" r=\"6\" fill=\"none\" stroke=\"{PreviewStyle.WarningColour}\" stroke-width=\"2.5\"/><text x=\"{F(x + 40)}\" y=\"{F(ty)}\">warning, with its line ({path.Warnings.Count})</text>\n");
        if (path.Arms.Count > 0)
        {
            ty += 21;
            svg.Append(CultureInfo.InvariantCulture, $"<line x1=\"{F(x + 16)}\" y1=\"{F(ty - 4)}\" x2=\"{F(x + 32)}\" y2=\"{F(ty - 4)}\" stroke=\"{PreviewStyle.ArmStartColour}\" stroke-width=\"6\" stroke-linecap=\"round\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<line x1=\"{F(x + 36)}\" y1=\"{F(ty - 4)}\" x2=\"{F(x + 52)}\" y2=\"{F(ty - 4)}\" stroke=\"{PreviewStyle.ArmEndColour}\" stroke-width=\"6\" stroke-linecap=\"round\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 62)}\" y=\"{F(ty)}\">the arm at the start (light) and the end (dark), base at 0,0,0</text>\n");
        }
        if (path.Reach is ReachEnvelope reach)
        {
            ty += 21;
            svg.Append(CultureInfo.InvariantCulture, $"<line x1=\"{F(x + 16)}\" y1=\"{F(ty - 4)}\" x2=\"{F(x + 52)}\" y2=\"{F(ty - 4)}\" class=\"reach\"/>");
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 62)}\" y=\"{F(ty)}\">reach: the flange cannot get beyond this line (up to {reach.Radius:0} mm out)</text>\n");
        }
        ty += 24;
        svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 14)}\" y=\"{F(ty)}\" class=\"small\">Extent: X {G(min.X)} to {G(max.X)}, Y {G(min.Y)} to {G(max.Y)}, Z {G(min.Z)} to {G(max.Z)} mm</text>\n");
        if (path.Warnings.Count > 0)
        {
            ty += 26;
            svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + 14)}\" y=\"{F(ty)}\" font-weight=\"600\" fill=\"{PreviewStyle.WarningColour}\">Warnings</text>\n");
            // Each warning whole or not at all, and a last line that counts the ones left out: no warning is cut or dropped unsaid.
            int listed = 0;
            foreach (PathWarning warning in path.Warnings.Take(MaxListedWarnings))
            {
                IReadOnlyList<string> lines = Wrap($"line {warning.Line}: {warning.Instruction} {warning.Message}", WarningLineLength, MaxWarningLines);
                double needed = 17 + (14 * (lines.Count - 1)) + (listed + 1 < path.Warnings.Count ? 17 : 0);
                if (ty + needed > y + h - 8)
                {
                    break;
                }
                for (int i = 0; i < lines.Count; i++)
                {
                    ty += i == 0 ? 17 : 14;
                    svg.Append(CultureInfo.InvariantCulture, $"<text x=\"{F(x + (i == 0 ? 14 : 26))}\" y=\"{F(ty)}\" class=\"small\">{Esc(lines[i])}</text>\n");
                }
                listed++;
            }
            if (listed < path.Warnings.Count)
            {
                ty += 17;
                svg.Append(CultureInfo.InvariantCulture,
                    $"<text x=\"{F(x + 14)}\" y=\"{F(ty)}\" class=\"small\">… and {path.Warnings.Count - listed} more (every warning is on the command's output, with its line)</text>\n");
            }
        }
        svg.Append("</g>\n");
    }

    /// <summary>Consecutive segments of one kind that join up, as one polyline each.</summary>
    internal static IEnumerable<(SegmentKind Kind, List<Vector> Points)> Runs(IReadOnlyList<PathSegment> segments)
    {
        List<Vector>? run = null;
        SegmentKind kind = SegmentKind.Linear;
        foreach (PathSegment segment in segments)
        {
            if (run is not null && segment.Kind == kind && run[^1] == segment.Points[0])
            {
                run.AddRange(segment.Points.Skip(1));
                continue;
            }
            if (run is not null)
            {
                yield return (kind, run);
            }
            run = [.. segment.Points];
            kind = segment.Kind;
        }
        if (run is not null)
        {
            yield return (kind, run);
        }
    }

    /// <summary>1, 2 or 5 times a power of ten, at least <paramref name="rough"/>.</summary>
    internal static double NiceStep(double rough)
    {
        double power = Math.Pow(10, Math.Floor(Math.Log10(Math.Max(rough, 1e-6))));
        foreach (double m in new[] { 1.0, 2, 5, 10 })
        {
            if (m * power >= rough)
            {
                return m * power;
            }
        }
        return 10 * power;
    }

    /// <summary>Characters of a warning per legend line (11 px text in the legend's width), and most lines per warning.</summary>
    private const int WarningLineLength = 92, MaxWarningLines = 3;

    /// <summary>
    /// <paramref name="text"/> in lines of at most <paramref name="width"/> characters, broken between words; at most
    /// <paramref name="maxLines"/> lines, the last ending in "…" when text is left over.
    /// </summary>
    internal static IReadOnlyList<string> Wrap(string text, int width, int maxLines)
    {
        var lines = new List<string>();
        int start = 0;
        while (start < text.Length)
        {
            if (lines.Count == maxLines - 1 && text.Length - start > width)
            {
                lines.Add(text[start..(start + width - 1)].TrimEnd() + "…");
                return lines;
            }
            int end = Math.Min(text.Length, start + width);
            if (end < text.Length)
            {
                int space = text.LastIndexOf(' ', end - 1, end - start);
                end = space > start ? space : end;
            }
            lines.Add(text[start..end].Trim());
            start = end;
            while (start < text.Length && text[start] == ' ')
            {
                start++;
            }
        }
        return lines;
    }

    private static string P(Vector? p) => p is Vector v ? $"[{G(v.X)}, {G(v.Y)}, {G(v.Z)}] mm" : "unknown";

    /// <summary>A coordinate as written in the file: up to 3 decimals, invariant culture.</summary>
    internal static string F(double value) => value.ToString("0.###", CultureInfo.InvariantCulture);

    private static string F6(double value) => value.ToString("0.######", CultureInfo.InvariantCulture);

    private static string G(double value) => value.ToString("0.##", CultureInfo.InvariantCulture);

    private static string Esc(string text) => SecurityElement.Escape(text);
}

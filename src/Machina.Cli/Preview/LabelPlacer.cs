namespace Machina.Cli.Preview;

/// <summary>A label's place: the baseline's start (or end, for <c>Anchor == "end"</c>), in picture pixels.</summary>
internal readonly record struct LabelSpot(double X, double Y, string Anchor);

/// <summary>
/// Places the labels of a view's markers (start, end, base, warnings) so that no two overlap: each label tries its own
/// corner of its marker first (the start below right, the end above right, a warning above left, the base below), then the
/// other corners, then further up or down its own side, and keeps the first place that is free of the labels placed before
/// it and of the other markers. Text boxes are estimated from the font size, generously (a font's ascent and descent can reach 1.4 em).
/// </summary>
internal sealed class LabelPlacer
{
    private readonly List<(double X0, double Y0, double X1, double Y1)> _taken = [];

    /// <summary>Keeps a marker's box (<paramref name="halfWidth"/> and <paramref name="halfHeight"/> around its middle) free of labels.</summary>
    internal void AddMarker(double x, double y, double halfWidth, double halfHeight) => _taken.Add((x - halfWidth, y - halfHeight, x + halfWidth, y + halfHeight));

    /// <summary>Where to write <paramref name="text"/> of <paramref name="fontSize"/> px beside the marker at (<paramref name="x"/>, <paramref name="y"/>).</summary>
    internal LabelSpot Place(double x, double y, string text, double fontSize, LabelCorner preferred)
    {
        double width = (text.Length * fontSize * 0.7) + 2;
        LabelSpot? first = null;
        foreach (LabelSpot spot in Candidates(x, y, preferred, fontSize))
        {
            first ??= spot;
            var box = Box(spot, width, fontSize);
            if (!_taken.Any(t => box.X0 < t.X1 && t.X0 < box.X1 && box.Y0 < t.Y1 && t.Y0 < box.Y1))
            {
                _taken.Add(box);
                return spot;
            }
        }
        // Crowded everywhere near the marker: its own corner, as before.
        _taken.Add(Box(first!.Value, width, fontSize));
        return first!.Value;
    }

    private static (double X0, double Y0, double X1, double Y1) Box(LabelSpot spot, double width, double fontSize)
    {
        double x0 = spot.Anchor == "end" ? spot.X - width : spot.Anchor == "middle" ? spot.X - (width / 2) : spot.X;
        return (x0, spot.Y - (1.1 * fontSize), x0 + width, spot.Y + (0.35 * fontSize));
    }

    private static IEnumerable<LabelSpot> Candidates(double x, double y, LabelCorner preferred, double fontSize)
    {
        LabelSpot AboveRight(double shift) => new(x + 9, y - 8 - shift, "start");
        LabelSpot BelowRight(double shift) => new(x + 9, y + 16 + shift, "start");
        LabelSpot AboveLeft(double shift) => new(x - 8, y - 8 - shift, "end");
        LabelSpot BelowLeft(double shift) => new(x - 8, y + 16 + shift, "end");
        LabelSpot Below(double shift) => new(x, y + 18 + shift, "middle");
        Func<double, LabelSpot>[] corners = preferred switch
        {
            LabelCorner.AboveRight => [AboveRight, BelowRight, AboveLeft, BelowLeft],
            LabelCorner.BelowRight => [BelowRight, AboveRight, BelowLeft, AboveLeft],
            LabelCorner.AboveLeft => [AboveLeft, BelowLeft, AboveRight, BelowRight],
            _ => [Below, BelowRight, BelowLeft, AboveRight, AboveLeft],
        };
        for (int step = 0; step <= 8; step++)
        {
            foreach (Func<double, LabelSpot> corner in corners)
            {
                yield return corner(step * ((1.5 * fontSize) + 1));
            }
        }
    }
}

/// <summary>The corner of its marker a label tries first.</summary>
internal enum LabelCorner
{
    /// <summary>Above and to the right (the end).</summary>
    AboveRight,

    /// <summary>Below and to the right (the start).</summary>
    BelowRight,

    /// <summary>Above and to the left (a warning).</summary>
    AboveLeft,

    /// <summary>Centred below (the base).</summary>
    Below,
}

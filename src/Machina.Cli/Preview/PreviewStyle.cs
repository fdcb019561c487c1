namespace Machina.Cli.Preview;

/// <summary>Colours and names of the segment kinds, shared by the SVG and the 3D view so that both read the same.</summary>
internal static class PreviewStyle
{
    /// <summary>Colour of the start marker.</summary>
    internal const string StartColour = "#2e7d32";

    /// <summary>Colour of the end marker.</summary>
    internal const string EndColour = "#212121";

    /// <summary>Colour of the warning markers.</summary>
    internal const string WarningColour = "#e53935";

    /// <summary>Colours of the arm drawn at the start, at the end and where a warning is.</summary>
    internal const string ArmStartColour = "#c3cad4", ArmEndColour = "#8d97a5", ArmWarningColour = "#f2aaa7";

    /// <summary>Colour of the reach envelope's outline.</summary>
    internal const string ReachColour = "#7f8c9b";

    /// <summary>The class name and CSS colour of a kind.</summary>
    internal static (string Name, string Colour, string Label) Of(SegmentKind kind) => kind switch
    {
        SegmentKind.Linear => ("linear", "#1e6fd9", "linear move (straight line)"),
        SegmentKind.Joint => ("joint", "#f08c00", "joint move (drawn straight; the real path curves)"),
        SegmentKind.Arc => ("arc", "#8e44ad", "arc move"),
        SegmentKind.Travel => ("travel", "#9e9e9e", "travel (not extruding)"),
        SegmentKind.Extrusion => ("extrusion", "#00a388", "extrusion"),
        _ => ("other", "#000000", "other"),
    };

    /// <summary>The legend text of a kind in <paramref name="path"/>: joint moves follow the arm when a model was given.</summary>
    internal static string Label(SegmentKind kind, PreviewPath path) =>
        kind == SegmentKind.Joint && path.JointsFollowTheArm ? "joint move (the tool path as the joints turn)" : Of(kind).Label;

    /// <summary>Every kind, in legend order.</summary>
    internal static readonly SegmentKind[] Kinds = [SegmentKind.Linear, SegmentKind.Joint, SegmentKind.Arc, SegmentKind.Travel, SegmentKind.Extrusion];
}

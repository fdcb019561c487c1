using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes inline robtargets as <see cref="RapidText.RobTarget"/> does, keeping the text after the position (orientation,
/// configuration, external axes) of the last target: a toolpath keeps its orientation over millions of moves, and its four
/// quaternion numbers and six axis values are then copied instead of formatted again.
/// </summary>
internal sealed class RapidTargetText
{
    private readonly StringBuilder _tail = new(128);
    private bool _known;
    private Rotation _rotation;
    private ExternalAxes? _axes;
    private double? _armAngle;
    private AbbConfiguration? _conf;

    /// <summary>Counts the times the kept text was written anew: the same count means the same <see cref="Tail"/> text.</summary>
    internal int Version { get; private set; }

    /// <summary>Appends the robtarget <c>[[x, y, z], [q1, q2, q3, q4], conf, external axes]</c>; the same text as <see cref="RapidText.RobTarget"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal StringBuilder Append(StringBuilder sb, Vector position, Rotation rotation, ExternalAxes? axes, double? armAngle, AbbConfiguration? conf) =>
        sb.Append('[').Position(position).Append(Tail(rotation, axes, armAngle, conf));

    /// <summary>The robtarget's text after the position, <c>, [q1, q2, q3, q4], conf, external axes]</c>, kept while its values stay the same.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal StringBuilder Tail(Rotation rotation, ExternalAxes? axes, double? armAngle, AbbConfiguration? conf)
    {
        if (!_known || rotation != _rotation || axes != _axes || armAngle != _armAngle || conf != _conf)
        {
            _tail.Clear().Append(", ").Quaternion(rotation).Append(", ").Append(conf is AbbConfiguration c ? c.ToRapid() : "[0,0,0,0]").Append(", ")
                 .ExternalAxes(axes, armAngle).Append(']');
            _known = true;
            _rotation = rotation;
            _axes = axes;
            _armAngle = armAngle;
            _conf = conf;
            Version++;
        }
        return _tail;
    }
}

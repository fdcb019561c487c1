using System.Runtime.CompilerServices;
using System.Text;

namespace Machina;

/// <summary>
/// Writes inline robtargets as <see cref="RapidText.RobTarget"/> does, keeping the text after the position of the last target in
/// two parts: the orientation's four quaternion numbers, and the configuration and six external axis values after them. A
/// toolpath keeps its orientation over millions of moves and both parts are then copied instead of formatted again; a path that
/// turns on every other move formats only its quaternion anew.
/// </summary>
internal sealed class RapidTargetText
{
    private readonly StringBuilder _tail = new(128);
    private readonly StringBuilder _rest = new(96);
    private readonly char[] _quaternion = new char[4 * (NumAppend.MaxChars + 2) + 2];
    private int _quaternionLength;
    private bool _rotationKnown, _restKnown, _tailKnown;
    private Rotation _rotation;
    private ExternalAxes? _axes;
    private double? _armAngle;
    private AbbConfiguration? _conf;
    private int _tailRestVersion;

    /// <summary>Counts the times the kept text after the quaternion was written anew: the same count means the same <see cref="Rest"/> text.</summary>
    internal int RestVersion { get; private set; }

    /// <summary>Appends the robtarget <c>[[x, y, z], [q1, q2, q3, q4], conf, external axes]</c>; the same text as <see cref="RapidText.RobTarget"/>.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal StringBuilder Append(StringBuilder sb, Vector position, Rotation rotation, ExternalAxes? axes, double? armAngle, AbbConfiguration? conf) =>
        sb.Append('[').Position(position).Append(Tail(rotation, axes, armAngle, conf));

    /// <summary>The robtarget's text after the position, <c>, [q1, q2, q3, q4], conf, external axes]</c>, kept while its values stay the same.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal StringBuilder Tail(Rotation rotation, ExternalAxes? axes, double? armAngle, AbbConfiguration? conf)
    {
        bool turned = !_rotationKnown || rotation != _rotation;
        ReadOnlySpan<char> quaternion = Quaternion(rotation);
        StringBuilder rest = Rest(axes, armAngle, conf);
        if (!_tailKnown || turned || _tailRestVersion != RestVersion)
        {
            _tail.Clear().Append(", ").Append(quaternion).Append(rest);
            (_tailKnown, _tailRestVersion) = (true, RestVersion);
        }
        return _tail;
    }

    /// <summary>The quaternion's text <c>[q1, q2, q3, q4]</c> (4 decimals, as <see cref="RapidText.Quaternion"/>), kept while the orientation stays the same.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal ReadOnlySpan<char> Quaternion(Rotation rotation)
    {
        if (!_rotationKnown || rotation != _rotation)
        {
            Span<char> text = _quaternion;
            int at = 0;
            text[at++] = '[';
            at = Number(text, at, rotation.W);
            at = Number(text, at, rotation.X);
            at = Number(text, at, rotation.Y);
            at = Number(text, at, rotation.Z);
            text[at - 2] = ']';
            (_quaternionLength, _rotation, _rotationKnown) = (at - 1, rotation, true);
        }
        return _quaternion.AsSpan(0, _quaternionLength);
    }

    /// <summary>
    /// The text after the quaternion, <c>, conf, external axes]</c>, kept while the configuration and the axes stay the same
    /// (<see cref="RestVersion"/> counts its changes).
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal StringBuilder Rest(ExternalAxes? axes, double? armAngle, AbbConfiguration? conf)
    {
        if (!_restKnown || axes != _axes || armAngle != _armAngle || conf != _conf)
        {
            _rest.Clear().Append(", ").Append(conf is AbbConfiguration c ? c.ToRapid() : "[0,0,0,0]").Append(", ")
                 .ExternalAxes(axes, armAngle).Append(']');
            (_restKnown, _axes, _armAngle, _conf) = (true, axes, armAngle, conf);
            RestVersion++;
        }
        return _rest;
    }

    /// <summary>Writes one quaternion number and ", " after it (the last one's separator becomes the closing bracket).</summary>
    /// <remarks>A unit quaternion's components are at most 1 in size: their 4 decimals always fit the fast digits.</remarks>
    // Inlined into the optimised Quaternion: four calls a turn, and under the JIT it stayed unoptimised first-tier code all compile.
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    private static int Number(Span<char> text, int at, double value)
    {
        int written = NumAppend.TryWriteScaled(text[at..], value, RapidFacts.QuaternionDecimals);
        if (written < 0)
        {
            string general = NumAppend.Format(value, RapidFacts.QuaternionDecimals);
            general.CopyTo(text[at..]);
            written = general.Length;
        }
        at += written;
        text[at++] = ',';
        text[at++] = ' ';
        return at;
    }
}

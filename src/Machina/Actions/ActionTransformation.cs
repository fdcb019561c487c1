namespace Machina;

/// <summary>Moves and rotates the tool in one motion: to a pose (<c>TransformTo</c>) or by an offset and rotation (<c>Transform</c>).</summary>
public sealed record ActionTransformation : RobotAction
{
    /// <summary>Creates a transformation; <paramref name="translation"/> in mm.</summary>
    /// <param name="translation">Target position or offset, mm.</param>
    /// <param name="rotation">Target orientation or rotation.</param>
    /// <param name="relative">True for an offset and rotation, false for a target pose.</param>
    /// <param name="translationFirst">For relative local transformations: move first, then rotate (true) or the other way round.</param>
    public ActionTransformation(Vector translation, Rotation rotation, bool relative, bool translationFirst)
    {
        Translation = translation.RequireFinite(nameof(translation));
        Rotation = rotation;
        Relative = relative;
        TranslationFirst = translationFirst;
    }

    /// <summary>The target position or offset, mm.</summary>
    public Vector Translation { get; }

    /// <summary>The target orientation or the rotation.</summary>
    public Rotation Rotation { get; }

    /// <summary>True for an offset and rotation, false for a target pose.</summary>
    public bool Relative { get; }

    /// <summary>For relative transformations in the tool frame: translate before rotating.</summary>
    public bool TranslationFirst { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Transformation;

    /// <inheritdoc/>
    public override string ToInstruction()
    {
        Vector t = Translation;
        if (Relative)
        {
            AxisAngle aa = Rotation.ToAxisAngle().WithUnitAxis();
            Vector axis = InstructionText.Axis(aa.Axis);
            return InstructionText.Call("Transform", null, [t.X, t.Y, t.Z, axis.X, axis.Y, axis.Z, aa.Angle],
                TranslationFirst ? null : InstructionText.Bool(false));
        }
        Vector x = InstructionText.Axis(Rotation.XAxis), y = InstructionText.Axis(Rotation.YAxis);
        return InstructionText.Call("TransformTo", t.X, t.Y, t.Z, x.X, x.Y, x.Z, y.X, y.Y, y.Z);
    }

    /// <inheritdoc/>
    public override string Describe()
    {
        if (!Relative)
        {
            return $"Transform: move to {Translation} mm and rotate to {Rotation.ToOrientationString()}";
        }
        AxisAngle aa = Rotation.ToAxisAngle().WithUnitAxis();
        string move = $"move {Translation} mm";
        string rotate = $"rotate {Num.G(aa.Angle)} deg around {aa.Axis}";
        return TranslationFirst ? $"Transform: {move} and {rotate}" : $"Transform: {rotate} and {move}";
    }

    /// <summary>Equal when the translation agrees exactly, the rotations within 1e-9 degrees, and the flags (the order only for relative ones).</summary>
    public bool Equals(ActionTransformation? other) =>
        other is not null && Relative == other.Relative && (TranslationFirst == other.TranslationFirst || !Relative)
        && Translation == other.Translation && Rotation.IsSimilar(other.Rotation, 1e-9);

    /// <inheritdoc/>
    public override int GetHashCode() => HashCode.Combine(Type, Relative, Translation);
}

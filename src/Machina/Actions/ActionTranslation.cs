namespace Machina;

/// <summary>Moves the tool tip to a position (<c>MoveTo</c>) or by an offset (<c>Move</c>), in mm, keeping its orientation.</summary>
public sealed record ActionTranslation : RobotAction
{
    /// <summary>Creates a translation; <paramref name="translation"/> in mm.</summary>
    public ActionTranslation(Vector translation, bool relative)
    {
        Translation = translation.RequireFinite(nameof(translation));
        Relative = relative;
    }

    /// <summary>The target position (absolute) or offset (relative), mm.</summary>
    public Vector Translation { get; }

    /// <summary>True for an offset, false for a target position.</summary>
    public bool Relative { get; }

    /// <inheritdoc/>
    public override bool IsRelative => Relative;

    /// <inheritdoc/>
    public override ActionType Type => ActionType.Translation;

    /// <inheritdoc/>
    public override string ToInstruction() => InstructionText.Call(Relative ? "Move" : "MoveTo", Translation.X, Translation.Y, Translation.Z);

    /// <inheritdoc/>
    public override string Describe()
    {
        // Written into one buffer: compilers with human comments describe every move of a program of millions.
        ReadOnlySpan<char> verb = Relative ? "Move " : "Move to ";
        Span<char> buffer = stackalloc char[16 + Vector.MaxTextChars];
        verb.CopyTo(buffer);
        int at = verb.Length;
        at += Translation.WriteText(buffer[at..], ", ");
        " mm".CopyTo(buffer[at..]);
        return new string(buffer[..(at + 3)]);
    }
}

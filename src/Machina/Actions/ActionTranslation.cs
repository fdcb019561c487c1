using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>Moves the tool tip to a position (<c>MoveTo</c>) or by an offset (<c>Move</c>), in mm, keeping its orientation.</summary>
public sealed record ActionTranslation : RobotAction
{
    /// <summary>Creates a translation; <paramref name="translation"/> in mm.</summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
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

    /// <summary>
    /// Writes the text of <see cref="ToInstruction"/> (digits and fixed words only) into <paramref name="destination"/> (at least
    /// <see cref="MaxInstructionChars"/> long) and returns its length, without a string in between.
    /// </summary>
    internal int WriteInstruction(Span<char> destination) =>
        InstructionText.WriteCall(destination, Relative ? "Move" : "MoveTo", Translation.X, Translation.Y, Translation.Z);

    /// <summary>Characters enough for <see cref="WriteInstruction"/>.</summary>
    internal const int MaxInstructionChars = 9 + 3 * (NumAppend.MaxChars + 1);

    /// <inheritdoc/>
    public override string Describe()
    {
        Span<char> buffer = stackalloc char[MaxDescriptionChars];
        return new string(buffer[..WriteDescription(buffer)]);
    }

    /// <summary>Characters enough for <see cref="WriteDescription"/>.</summary>
    internal const int MaxDescriptionChars = 16 + Vector.MaxTextChars;

    /// <inheritdoc/>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override int TryWriteDescription(Span<char> destination) => WriteDescription(destination);

    /// <inheritdoc/>
    internal override int TryWriteInstruction(Span<char> destination) => WriteInstruction(destination);

    /// <inheritdoc/>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal override int TryWriteDescriptionAscii(Span<byte> destination)
    {
        ReadOnlySpan<byte> verb = Relative ? "Move "u8 : "Move to "u8;
        verb.CopyTo(destination);
        int at = verb.Length;
        int written = DescriptionAscii.TryWriteVector(destination[at..], Translation);
        if (written < 0)
        {
            return -1;
        }
        at += written;
        " mm"u8.CopyTo(destination[at..]);
        return at + 3;
    }

    /// <summary>
    /// Writes the text of <see cref="Describe"/> into <paramref name="destination"/> and returns its length: compilers with human
    /// comments describe every move of a program of millions, and copy it into their line without a string in between.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveOptimization)]
    internal int WriteDescription(Span<char> destination)
    {
        ReadOnlySpan<char> verb = Relative ? "Move " : "Move to ";
        verb.CopyTo(destination);
        int at = verb.Length;
        at += Translation.WriteText(destination[at..], ", ");
        " mm".CopyTo(destination[at..]);
        return at + 3;
    }
}

namespace Machina;

/// <summary>
/// One platform-agnostic instruction for a robot ("move 10 mm up", "set speed to 100"). Actions are immutable;
/// a robot gives each one an <see cref="Id"/> when it is issued. Two actions are equal when they say the same thing,
/// whatever their ids.
/// </summary>
public abstract record RobotAction
{
    /// <summary>The id the robot gave this action when it was issued (1, 2, 3, …), or −1 before that.</summary>
    public int Id { get => _id; internal set => _id = value; }

    private int _id = -1;

    /// <summary>
    /// The joints the last cursor solved for this motion and from which state (a robot with a model applies each motion on its
    /// issue, release and execution cursors; the later ones reuse the solution when they start from the same state).
    /// </summary>
    internal SolvedPose? Solved;

    /// <summary>The kind of action.</summary>
    public abstract ActionType Type { get; }

    /// <summary>True when the action is relative to the current state (<c>Move</c>), false when absolute (<c>MoveTo</c>) or neither.</summary>
    public virtual bool IsRelative => false;

    /// <summary>The instruction text that creates this action, e.g. <c>MoveTo(400,300,500);</c>; <c>Robot.Do</c> reads it back.</summary>
    public abstract string ToInstruction();

    /// <summary>A sentence describing the action for people, e.g. <c>Move to [400, 300, 500] mm</c>.</summary>
    public abstract string Describe();

    /// <summary>Same as <see cref="Describe"/>.</summary>
    public sealed override string ToString() => Describe();

    /// <summary>Characters enough for <see cref="TryWriteDescription"/>.</summary>
    internal const int MaxWrittenDescriptionChars = 64 + Vector.MaxTextChars;

    /// <summary>
    /// Writes the text of <see cref="Describe"/> into <paramref name="destination"/> (at least <see cref="MaxWrittenDescriptionChars"/>
    /// long) and returns its length, or −1 when this kind of action does not write it so (call <see cref="Describe"/>). Only
    /// descriptions of digits and fixed words are written so: they are safe in every language's comment as they are, and a
    /// compile of millions of moves and turns describes each one without a string in between.
    /// </summary>
    internal virtual int TryWriteDescription(Span<char> destination) => -1;

    /// <summary>
    /// Writes the ASCII bytes of what <see cref="TryWriteDescription"/> writes (at least <see cref="MaxWrittenDescriptionChars"/>
    /// bytes of room) and returns their count, or −1 when this action's description is not written so (a number in .NET's
    /// general text, or a kind of action that writes none: call <see cref="TryWriteDescription"/>). For compilers that write
    /// their lines as bytes (<see cref="LineSink.BeginAscii"/>): no characters narrowed per line.
    /// </summary>
    internal virtual int TryWriteDescriptionAscii(Span<byte> destination) => -1;

    /// <summary>Characters enough for <see cref="TryWriteInstruction"/>.</summary>
    internal const int MaxWrittenInstructionChars = 16 + 6 * (NumAppend.MaxChars + 1);

    /// <summary>
    /// Writes the text of <see cref="ToInstruction"/> into <paramref name="destination"/> (at least
    /// <see cref="MaxWrittenInstructionChars"/> long) and returns its length, or −1 when this kind of action does not write it so
    /// (call <see cref="ToInstruction"/>). Like <see cref="TryWriteDescription"/>, only for digits and fixed words.
    /// </summary>
    internal virtual int TryWriteInstruction(Span<char> destination) => -1;

    /// <summary>Compares what two actions say, ignoring their ids.</summary>
    public virtual bool Equals(RobotAction? other) => other is not null && EqualityContract == other.EqualityContract;

    /// <summary>Hash of what the action says, ignoring its id.</summary>
    public override int GetHashCode() => EqualityContract.GetHashCode();

    /// <summary>
    /// Gives this unissued action <paramref name="id"/>, atomically: false when it already has one (another robot may be issuing
    /// the same object on another thread at this moment).
    /// </summary>
    internal bool TryClaimId(int id) => Interlocked.CompareExchange(ref _id, id, -1) == -1;

    /// <summary>A copy of this action that has not been issued yet.</summary>
    internal RobotAction CloneUnissued()
    {
        var copy = this with { };
        copy.Id = -1;
        copy.Solved = null;
        return copy;
    }
}

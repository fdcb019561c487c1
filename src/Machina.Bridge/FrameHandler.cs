namespace Machina.Bridge;

/// <summary>What became of one message of instructions.</summary>
internal enum FrameOutcome
{
    /// <summary>Every instruction was issued; each one's <c>action-issued</c> event goes to every client.</summary>
    Accepted,

    /// <summary>Nothing was issued; the reply (an <c>error</c> event) goes to the sender only.</summary>
    Rejected,

    /// <summary>No controller is connected; nothing was issued and the reply (<c>controller-disconnected</c>) goes to every client.</summary>
    NoController,
}

/// <summary>The outcome of a message and the JSON reply the bridge sends for it, if any.</summary>
internal readonly record struct FrameResult(FrameOutcome Outcome, string? Reply);

/// <summary>
/// Turns one text message into robot actions. A message holds any number of instructions; they are issued together or,
/// when one is malformed or refused, not at all. Only the exceptions documented for <see cref="Robot.Do"/> become error
/// events; any other exception is a bug and is left to the caller.
/// </summary>
internal sealed class FrameHandler(Robot robot, Func<bool> isConnected)
{
    /// <summary>Issues the instructions in <paramref name="text"/> and says what to answer.</summary>
    internal FrameResult Handle(string text)
    {
        ArgumentNullException.ThrowIfNull(text);
        if (!isConnected())
        {
            return new(FrameOutcome.NoController, BridgeEvents.ControllerDisconnected);
        }
        try
        {
            if (HoldsNoInstruction(text))
            {
                return Rejected(BridgeEvents.Error(BridgeEvents.Kinds.Empty, "The message holds no instruction; send text such as MoveTo(400,300,500);"));
            }
            robot.Do(ClientAliases.Translate(text));
            return new(FrameOutcome.Accepted, null);
        }
        catch (InstructionParseException e)
        {
            return Rejected(BridgeEvents.ParseError(e));
        }
        catch (ActionRefusedException e)
        {
            return Rejected(BridgeEvents.Refused(e));
        }
    }

    private static FrameResult Rejected(string reply) => new(FrameOutcome.Rejected, reply);

    /// <summary>
    /// True when the text holds only what the instruction reader skips between statements: white space, ';', a byte order
    /// mark and <c>//</c> comments. Anything else is an instruction or an error, so an empty message is told apart without
    /// reading the text twice.
    /// </summary>
    internal static bool HoldsNoInstruction(string text)
    {
        for (int i = 0; i < text.Length; i++)
        {
            char c = text[i];
            if (c == '/' && i + 1 < text.Length && text[i + 1] == '/')
            {
                int end = text.IndexOf('\n', i);
                if (end < 0)
                {
                    return true;
                }
                i = end;
            }
            else if (!char.IsWhiteSpace(c) && c != ';' && c != '\uFEFF')
            {
                return false;
            }
        }
        return true;
    }
}

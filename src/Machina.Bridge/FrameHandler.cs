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
            // Reads only up to the first instruction: cheap, and an empty message is told apart from a malformed one.
            if (!Instructions.Enumerate(text).Any())
            {
                return Rejected(BridgeEvents.Error(BridgeEvents.Kinds.Empty, "The message holds no instruction; send text such as MoveTo(400,300,500);"));
            }
            robot.Do(text);
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
}

using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal static partial class UrBuiltins
{
    /// <summary>
    /// Runs one of the controller's motions with the other threads free meanwhile (the machine's lock is taken back after, also
    /// when it throws); a motion the arm refuses is the program's runtime error at <paramref name="line"/>, named after
    /// <paramref name="function"/>. The state is passed by value so that a static lambda allocates nothing per call.
    /// </summary>
    private static TResult Unlocked<TState, TResult>(UrMachine m, int line, string function, TState state, Func<UrTwinController, TState, CancellationToken, TResult> motion)
    {
        CancellationToken token = m.Cancellation;
        try
        {
            using (m.Unlock())
            {
                return motion(m.Controller, state, token);
            }
        }
        catch (TwinMotionException e)
        {
            throw new UrRuntimeException(line, $"{function}: {e.Message}");
        }
    }
}

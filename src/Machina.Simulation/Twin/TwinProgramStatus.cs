namespace Machina.Simulation.Twin;

/// <summary>
/// How a twin's program (or one of its tasks) stands: its state and the message of the error that stopped it, read and written
/// together under one lock, so that nobody sees a state with another run's error.
/// </summary>
/// <typeparam name="TState">The language's program state.</typeparam>
internal sealed class TwinProgramStatus<TState>
    where TState : struct, Enum
{
    private readonly Lock _gate = new();
    private TState _state;
    private string? _error;

    /// <summary>The state (the language's Running while a program runs).</summary>
    public TState State
    {
        get
        {
            lock (_gate)
            {
                return _state;
            }
        }
    }

    /// <summary>The message of the error that stopped the last run, or null.</summary>
    public string? Error
    {
        get
        {
            lock (_gate)
            {
                return _error;
            }
        }
    }

    /// <summary>Records a state and its error; <paramref name="meanwhile"/> runs in the same step (nobody sees the state between).</summary>
    public void Set(TState state, string? error, Action? meanwhile = null)
    {
        lock (_gate)
        {
            meanwhile?.Invoke();
            _state = state;
            _error = error;
        }
    }

    /// <summary>
    /// Records <paramref name="error"/> with the state <paramref name="next"/> makes of the current one, or changes nothing when it
    /// gives null; true when it changed.
    /// </summary>
    public bool Change(Func<TState, TState?> next, string? error)
    {
        lock (_gate)
        {
            if (next(_state) is not { } state)
            {
                return false;
            }
            _state = state;
            _error = error;
            return true;
        }
    }
}

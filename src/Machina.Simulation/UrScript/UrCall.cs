namespace Machina.Simulation.UrScript;

/// <summary>A call <c>name(a, b, key=c)</c>; the binder resolves it to a built-in or a function of the program.</summary>
internal sealed class UrCall(int line, string name, List<UrExpr> positional, List<(string Name, UrExpr Value)> named) : UrExpr(line)
{
    /// <summary>The called name.</summary>
    public string Name { get; } = name;

    /// <summary>Arguments given by position.</summary>
    public List<UrExpr> Positional { get; } = positional;

    /// <summary>Arguments given by name.</summary>
    public List<(string Name, UrExpr Value)> Named { get; } = named;

    /// <summary>The built-in called, once bound.</summary>
    public UrBuiltin? Builtin { get; set; }

    /// <summary>The program's function called, once bound.</summary>
    public UrFunction? Function { get; set; }

    /// <summary>One expression per parameter, in parameter order (defaults filled in), once bound.</summary>
    public UrExpr[] Arguments { get; set; } = [];

    /// <inheritdoc/>
    public override object Eval(UrFrame frame)
    {
        UrStack.Check(frame, Line);
        if (Builtin is null)
        {
            // A function of the program: the arguments go straight into its frame's first locals (its parameters).
            // The frame ends with the call (URScript has no closures): its array is the thread's again afterwards.
            UrFunction function = Function!;
            object?[] locals = frame.Scratch.Rent(Math.Max(function.LocalCount, Arguments.Length));
            for (int i = 0; i < Arguments.Length; i++)
            {
                locals[i] = Arguments[i].Eval(frame);
            }
            object result = function.InvokeWithLocals(frame.Machine, Line, locals, frame.Depth + 1, frame.Scratch);
            frame.Scratch.Return(locals);
            return result;
        }
        // A built-in keeps none of its arguments (UrBuiltin): the array is the thread's again after the call.
        object?[] values = frame.Scratch.Rent(Arguments.Length);
        for (int i = 0; i < values.Length; i++)
        {
            values[i] = Arguments[i].Eval(frame);
        }
        object value = Builtin.Invoke(frame.Machine, Line, values!);
        frame.Scratch.Return(values);
        return value;
    }
}

/// <summary><c>run name()</c>: starts a thread of the program and gives its handle.</summary>
internal sealed class UrRunExpr(int line, string name) : UrExpr(line)
{
    /// <summary>The thread's name.</summary>
    public string Name { get; } = name;

    /// <summary>The thread definition, once bound.</summary>
    public UrFunction? Thread { get; set; }

    /// <inheritdoc/>
    public override object Eval(UrFrame frame) => frame.Machine.StartThread(Thread!, Line);
}

/// <summary>The parameters and implementation of one built-in function, as in the Script Manual.</summary>
/// <param name="Name">The function's name.</param>
/// <param name="Parameters">Parameter names; a non-null default makes the parameter optional.</param>
/// <param name="Body">The implementation: machine, line and one value per parameter; it reads them during the call and keeps neither the
/// array nor a reference to it (the caller uses the array again: <see cref="UrScratch"/>).</param>
internal sealed record UrBuiltin(string Name, (string Name, object? Default)[] Parameters, Func<UrMachine, int, object[], object> Body)
{
    /// <summary>Runs the built-in.</summary>
    public object Invoke(UrMachine machine, int line, object[] args)
    {
        try
        {
            return Body(machine, line, args);
        }
        catch (ArgumentException e)
        {
            // A value the geometry refuses (a number past the largest double once in mm or degrees): the program's error.
            throw new UrRuntimeException(line, $"{Name}: {e.Message}");
        }
    }
}

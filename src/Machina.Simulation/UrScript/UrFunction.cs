using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

/// <summary>A function (<c>def</c>) or thread (<c>thread</c>) of a program.</summary>
internal sealed class UrFunction(int line, string name, string[] parameters, UrExpr?[] defaults, List<UrStmt> body, bool isThread)
{
    /// <summary>The 1-based line of the definition.</summary>
    public int Line { get; } = line;

    /// <summary>The function's name.</summary>
    public string Name { get; } = name;

    /// <summary>Parameter names (they are the first locals).</summary>
    public string[] Parameters { get; } = parameters;

    /// <summary>Default value of each parameter, or null when it is required.</summary>
    public UrExpr?[] Defaults { get; } = defaults;

    /// <summary>The statements.</summary>
    public List<UrStmt> Body { get; } = body;

    /// <summary>True for a <c>thread</c>.</summary>
    public bool IsThread { get; } = isThread;

    /// <summary>True for a top-level definition without parameters: the program itself, whose variables are the program's globals.</summary>
    public bool IsProgram { get; set; }

    /// <summary>How many local slots a call needs (set by the binder).</summary>
    public int LocalCount { get; set; }

    /// <summary>Runs the function with one value per parameter and gives what it returns.</summary>
    public object Invoke(UrMachine machine, int line, object[] args, int depth)
    {
        int most = machine.Limits.MaxCallDepth;
        if (depth > most)
        {
            throw new UrRuntimeException(line, $"too many nested calls (more than {most}) in '{Name}'");
        }
        UrStack.Check(line);
        var frame = new UrFrame(machine, new object?[LocalCount], depth);
        Array.Copy(args, frame.Locals, args.Length);
        UrStmt.Run(Body, frame);
        return frame.ReturnValue ?? UrNone.Value;
    }
}

/// <summary>The locals of one running call.</summary>
internal sealed class UrFrame(UrMachine machine, object?[] locals, int depth)
{
    /// <summary>The running program.</summary>
    public UrMachine Machine { get; } = machine;

    /// <summary>Local variable slots.</summary>
    public object?[] Locals { get; } = locals;

    /// <summary>Call depth.</summary>
    public int Depth { get; } = depth;

    /// <summary>The value of the <c>return</c> that ended the call.</summary>
    public object? ReturnValue { get; set; }
}

/// <summary>The guard of the interpreter's own stack: a program nested past it stops with an error, never the process.</summary>
internal static class UrStack
{
    /// <summary>Throws the program's error when the running thread has too little stack left for one more level.</summary>
    public static void Check(int line)
    {
        if (TwinLimits.StackLow)
        {
            throw new UrRuntimeException(line, "stack overflow: the calls and expressions are nested too deeply");
        }
    }
}

using System.Runtime.CompilerServices;
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

    /// <summary>True for a secondary program (<c>sec</c>): it runs beside the main program, in a single controller step.</summary>
    public bool IsSecondary { get; init; }

    /// <summary>True for a top-level definition without parameters: the program itself, whose variables are the program's globals.</summary>
    public bool IsProgram { get; set; }

    /// <summary>How many local slots a call needs (set by the binder).</summary>
    public int LocalCount { get; set; }

    /// <summary>Runs the function with one value per parameter and gives what it returns.</summary>
    public object Invoke(UrMachine machine, int line, object[] args, int depth)
    {
        var locals = new object?[Math.Max(LocalCount, args.Length)];
        Array.Copy(args, locals, args.Length);
        return InvokeWithLocals(machine, line, locals, depth, new UrScratch());
    }

    /// <summary>
    /// Runs the function in a frame of <paramref name="locals"/> (its parameters' values first, then empty slots) and gives what it returns;
    /// <paramref name="scratch"/> is the calling thread's.
    /// </summary>
    public object InvokeWithLocals(UrMachine machine, int line, object?[] locals, int depth, UrScratch scratch)
    {
        int most = machine.Limits.MaxCallDepth;
        if (depth > most)
        {
            throw new UrRuntimeException(line, $"too many nested calls (more than {most}) in '{Name}'");
        }
        UrStack.Check(line);
        var frame = new UrFrame(machine, locals, depth, scratch);
        UrStmt.Run(Body, frame);
        return frame.ReturnValue ?? UrNone.Value;
    }
}

/// <summary>The locals of one running call.</summary>
internal sealed class UrFrame(UrMachine machine, object?[] locals, int depth, UrScratch scratch)
{
    /// <summary>The running thread's arrays for arguments and locals.</summary>
    public UrScratch Scratch { get; } = scratch;

    /// <summary>The running program.</summary>
    public UrMachine Machine { get; } = machine;

    /// <summary>Local variable slots.</summary>
    public object?[] Locals { get; } = locals;

    /// <summary>Call depth.</summary>
    public int Depth { get; } = depth;

    /// <summary>The value of the <c>return</c> that ended the call.</summary>
    public object? ReturnValue { get; set; }

    /// <summary>Expressions evaluated in this frame, counted for <see cref="UrStack.Check(UrFrame, int)"/>.</summary>
    private int _evaluations;

    /// <summary>Counts an expression; true at every <see cref="TwinLimits.StackCheckEvery"/>th.</summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public bool TimeToCheckStack() => (++_evaluations & (TwinLimits.StackCheckEvery - 1)) == 0;
}

/// <summary>The guard of the interpreter's own stack: a program nested past it stops with an error, never the process.</summary>
internal static class UrStack
{
    /// <summary>Throws the program's error when the running thread has too little stack left for one more level.</summary>
    public static void Check(int line)
    {
        if (TwinLimits.StackLow)
        {
            throw Overflow(line);
        }
    }

    /// <summary>
    /// <see cref="Check(int)"/> at every <see cref="TwinLimits.StackCheckEvery"/>th expression of <paramref name="frame"/> (each
    /// call checks as its frame starts): the runtime's question is a thread-local lookup, dear at every expression, and a few
    /// levels between two questions use little of the stack it keeps free.
    /// </summary>
    [MethodImpl(MethodImplOptions.AggressiveInlining)]
    public static void Check(UrFrame frame, int line)
    {
        if (frame.TimeToCheckStack())
        {
            Check(line);
        }
    }

    private static UrRuntimeException Overflow(int line) => new(line, "stack overflow: the calls and expressions are nested too deeply");
}

namespace Machina.Simulation.Twin;

/// <summary>
/// The settings every language's twin controller has: the arm, where it starts, its clock, how much of its trace it keeps and
/// the interpreter's budgets. A language's options derive from these (a record: a verifier copies them with another start).
/// </summary>
internal abstract record TwinOptions
{
    /// <summary>Settings with the language's default arm <paramref name="model"/> and <paramref name="startJoints"/>.</summary>
    protected TwinOptions(RobotModel model, Joints startJoints)
    {
        Model = model;
        StartJoints = startJoints;
    }

    /// <summary>The arm model (each language's default: the arm its virtual controller has).</summary>
    public RobotModel Model { get; init; }

    /// <summary>The joints (degrees) the arm starts at.</summary>
    public Joints StartJoints { get; init; }

    /// <summary>The time source for real-time motion and waits.</summary>
    public TimeProvider Time { get; init; } = TimeProvider.System;

    /// <summary>True: motion and waits take their time on <see cref="Time"/>; false: they return at once (program time still adds up).</summary>
    public bool RealTime { get; init; }

    /// <summary>How many steps the arm's trace keeps at least (0: all, for a verification; a controller serving streams keeps the last few).</summary>
    public int MaxTrace { get; init; }

    /// <summary>The interpreter's budgets (nesting, expression size, calls, steps, strings, arrays, program size).</summary>
    public TwinLimits Limits { get; init; } = TwinLimits.Default;
}

using System.Runtime.CompilerServices;

namespace Machina.Simulation.Twin;

/// <summary>
/// The budgets of a twin's interpreter (URScript, RAPID, KRL), as an embeddable interpreter offers them: whatever a program does,
/// it meets one of these as its own error (the controller's message, with the file and line; the program stops), never the process's.
/// docs/simulation.md ("Limits") sets each beside what the real controller allows.
/// </summary>
internal sealed record TwinLimits
{
    /// <summary>The budgets of a twin serving programs (no step budget: a controller runs a loop forever).</summary>
    public static TwinLimits Default { get; } = new();

    /// <summary>The budgets of a verification (<c>machina verify</c>): the default ones and <see cref="DefaultVerifySteps"/> statements.</summary>
    public static TwinLimits Verify { get; } = new() { MaxSteps = DefaultVerifySteps };

    /// <summary>The statements a verification runs before it stops the program as endless.</summary>
    public const long DefaultVerifySteps = 50_000_000;

    /// <summary>The largest program text, in characters (a file longer than this is refused before it is read whole).</summary>
    public long MaxProgramChars { get; init; } = 16 * 1024 * 1024;

    /// <summary>The deepest nesting of brackets, signs and blocks the parser reads.</summary>
    public int MaxNesting { get; init; } = 100;

    /// <summary>The most operators one expression holds.</summary>
    public int MaxExpressionOperators { get; init; } = 2_000;

    /// <summary>The deepest nesting of routine calls while a program runs.</summary>
    public int MaxCallDepth { get; init; } = 200;

    /// <summary>The statements a program may run before it is stopped (0: no limit).</summary>
    public long MaxSteps { get; init; }

    /// <summary>The longest string a program may build, in characters.</summary>
    public int MaxStringLength { get; init; } = 1024 * 1024;

    /// <summary>The most elements one array may hold.</summary>
    public int MaxArrayElements { get; init; } = 1_000_000;

    /// <summary>The most array elements the data of one program may hold at once.</summary>
    public long MaxTotalElements { get; init; } = 4_000_000;

    /// <summary>The most threads a program may have running at once (besides its own).</summary>
    public int MaxThreads { get; init; } = 64;

    /// <summary>The elements of an array of <paramref name="sizes"/>, or null when they are more than <see cref="MaxArrayElements"/> (checked arithmetic).</summary>
    public long? Elements(IEnumerable<int> sizes)
    {
        long count = 1;
        foreach (int size in sizes)
        {
            count *= Math.Max(size, 1);
            if (count > MaxArrayElements)
            {
                return null;
            }
        }
        return count;
    }

    /// <summary>The message of an array past <see cref="MaxArrayElements"/>.</summary>
    public string ArrayTooLarge(IEnumerable<int> sizes) =>
        $"the array {{{string.Join(",", sizes)}}} has more than {MaxArrayElements:N0} elements (the twin's limit)";

    /// <summary>
    /// How often an interpreter asks <see cref="StackLow"/> (a power of 2): at every 8th expression or call. A runtime call per
    /// expression cost 1-4 % of an interpreter's time; 7 levels between two questions use a few KB of the 64 KB and more that
    /// <see cref="RuntimeHelpers.TryEnsureSufficientExecutionStack"/> keeps free.
    /// </summary>
    public const int StackCheckEvery = 8;

    /// <summary>True when the calling thread has too little stack left to go one level deeper (the program then stops with an error).</summary>
    public static bool StackLow => !RuntimeHelpers.TryEnsureSufficientExecutionStack();
}

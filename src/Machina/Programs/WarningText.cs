using System.Runtime.CompilerServices;

namespace Machina;

/// <summary>
/// The text of a compiler warning, written only when the job keeps it: a long program can raise a warning on every line, and
/// past <see cref="CompileJob.MaxWarningsKept"/> warnings are only counted, so their messages are never formatted.
/// </summary>
[InterpolatedStringHandler]
internal ref struct WarningText
{
    private DefaultInterpolatedStringHandler _inner;

    /// <summary>Starts the text; <paramref name="wanted"/> is false when the job will only count the warning.</summary>
    public WarningText(int literalLength, int formattedCount, CompileJob job, out bool wanted)
    {
        wanted = job.KeepsMoreWarnings;
        _inner = wanted ? new DefaultInterpolatedStringHandler(literalLength, formattedCount, Num.Inv) : default;
        IsWanted = wanted;
    }

    /// <summary>False when the text was not written.</summary>
    internal readonly bool IsWanted { get; }

    /// <summary>Appends literal text.</summary>
    public void AppendLiteral(string value) => _inner.AppendLiteral(value);

    /// <summary>Appends a value, invariant culture.</summary>
    public void AppendFormatted<T>(T value) => _inner.AppendFormatted(value);

    /// <summary>Appends a value with a format, invariant culture.</summary>
    public void AppendFormatted<T>(T value, string? format) => _inner.AppendFormatted(value, format);

    /// <summary>Appends a string.</summary>
    public void AppendFormatted(string? value) => _inner.AppendFormatted(value);

    /// <summary>Appends characters (a piece of a line a compiler is writing).</summary>
    public void AppendFormatted(scoped ReadOnlySpan<char> value) => _inner.AppendFormatted(value);

    /// <summary>The text, once.</summary>
    internal string ToStringAndClear() => _inner.ToStringAndClear();
}

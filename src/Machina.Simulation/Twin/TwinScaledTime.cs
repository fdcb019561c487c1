namespace Machina.Simulation.Twin;

/// <summary>
/// The time a twin's interpreter (URScript, RAPID or KRL) waits on when the virtual controller's <c>SpeedFactor</c> is not 1: a
/// wait of d on it is a wait of d / factor on the controller's clock, so the robot's motion and sleeps run that many times faster
/// (its program time adds up unscaled). Timestamps run that many times faster from its creation, and the due time of a new timer
/// is scaled (what a motion's or a sleep's wait uses).
/// </summary>
internal sealed class TwinScaledTime(TimeProvider inner, double factor) : TimeProvider
{
    /// <summary>The time a twin runs on: <paramref name="clock"/> itself at factor 1, else <paramref name="clock"/> scaled.</summary>
    public static TimeProvider Of(TimeProvider clock, double factor) => factor == 1 ? clock : new TwinScaledTime(clock, factor);

    /// <summary>The wall clock under <paramref name="time"/>: the clock a scaled time runs faster than, else the time itself.</summary>
    public static TimeProvider Wall(TimeProvider time) => time is TwinScaledTime scaled ? scaled.Inner : time;

    private readonly long _origin = inner.GetTimestamp();

    /// <summary>The clock this one runs faster than.</summary>
    public TimeProvider Inner => inner;

    /// <summary>How many times faster than <see cref="Inner"/> it runs.</summary>
    public double Factor => factor;

    /// <inheritdoc/>
    public override long TimestampFrequency => inner.TimestampFrequency;

    /// <inheritdoc/>
    public override TimeZoneInfo LocalTimeZone => inner.LocalTimeZone;

    /// <inheritdoc/>
    public override long GetTimestamp() => _origin + (long)Math.Min((inner.GetTimestamp() - _origin) * factor, long.MaxValue / 4.0);

    /// <inheritdoc/>
    public override DateTimeOffset GetUtcNow() => inner.GetUtcNow();

    /// <inheritdoc/>
    public override ITimer CreateTimer(TimerCallback callback, object? state, TimeSpan dueTime, TimeSpan period) =>
        inner.CreateTimer(callback, state, Scale(dueTime), Scale(period));

    private TimeSpan Scale(TimeSpan span) =>
        span == Timeout.InfiniteTimeSpan || span <= TimeSpan.Zero ? span : TimeSpan.FromTicks(Math.Max(1, (long)(span.Ticks / factor)));
}

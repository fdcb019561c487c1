using System.Globalization;
using System.Text;

namespace Machina.Cli.Terminal;

/// <summary>
/// Shows how a streamed program is doing: on a terminal one line redrawn in place (bar, counts, rate, time left); when the
/// output is redirected, a plain line at every tenth of the program (or every 10 seconds when the total is unknown).
/// </summary>
internal sealed class ProgressReporter
{
    private const int BarWidth = 24;
    private static readonly TimeSpan RedrawPeriod = TimeSpan.FromMilliseconds(100);
    private static readonly TimeSpan PlainPeriod = TimeSpan.FromSeconds(10);

    private readonly CliContext _context;
    private readonly long? _total;
    private readonly long _start;
    private readonly Lock _gate = new();
    private long _lastDraw;
    private long _nextPlainStep;
    private int _drawnWidth;

    /// <summary>A reporter for a program of <paramref name="total"/> actions (null when unknown, e.g. standard input).</summary>
    internal ProgressReporter(CliContext context, long? total)
    {
        _context = context;
        _total = total is > 0 ? total : null;
        _start = context.Time.GetTimestamp();
        _lastDraw = long.MinValue;
        _nextPlainStep = 1;
    }

    /// <summary>Reports that <paramref name="executed"/> actions are done; <paramref name="line"/> is the program line of the last one.</summary>
    internal void Update(long executed, int line)
    {
        lock (_gate)
        {
            long now = _context.Time.GetTimestamp();
            if (_context.IsTerminal)
            {
                if (_lastDraw != long.MinValue && _context.Time.GetElapsedTime(_lastDraw, now) < RedrawPeriod && executed != _total)
                {
                    return;
                }
                _lastDraw = now;
                string text = Line(executed, line, now);
                _context.Stdout.Write("\r" + text.PadRight(_drawnWidth));
                _context.Stdout.Flush();
                _drawnWidth = text.Length;
                return;
            }
            bool due = _total is long total
                ? executed * 10 >= _nextPlainStep * total
                : _lastDraw == long.MinValue || _context.Time.GetElapsedTime(_lastDraw, now) >= PlainPeriod;
            if (!due)
            {
                return;
            }
            if (_total is long t)
            {
                while (executed * 10 >= _nextPlainStep * t)
                {
                    _nextPlainStep++;
                }
            }
            _lastDraw = now;
            _context.Stdout.WriteLine(Line(executed, line, now));
        }
    }

    /// <summary>Ends the redrawn line (terminal) so that what follows starts on a new line.</summary>
    internal void Finish()
    {
        lock (_gate)
        {
            if (_context.IsTerminal && _drawnWidth > 0)
            {
                _context.Stdout.WriteLine();
                _drawnWidth = 0;
            }
        }
    }

    /// <summary>The progress text, e.g. <c>[######------]  50%  500/1000 actions  120.5/s  0:04 left  line 501</c>.</summary>
    internal string Line(long executed, int line, long now)
    {
        double seconds = _context.Time.GetElapsedTime(_start, now).TotalSeconds;
        double rate = seconds > 0 ? executed / seconds : 0;
        var sb = new StringBuilder();
        if (_total is long total)
        {
            double fraction = Math.Clamp((double)executed / total, 0, 1);
            if (_context.IsTerminal)
            {
                int filled = (int)Math.Round(fraction * BarWidth);
                sb.Append('[').Append('#', filled).Append('-', BarWidth - filled).Append("] ");
            }
            sb.Append(CultureInfo.InvariantCulture, $"{fraction * 100,3:0}%  {executed}/{total} {Counted.Noun(total, "action")}");
            sb.Append(CultureInfo.InvariantCulture, $"  {rate:0.0}/s");
            if (rate > 0 && executed < total)
            {
                sb.Append("  ").Append(Duration((total - executed) / rate)).Append(" left");
            }
        }
        else
        {
            sb.Append(CultureInfo.InvariantCulture, $"{Counted.Of(executed, "action")}  {rate:0.0}/s");
        }
        if (line > 0)
        {
            sb.Append(CultureInfo.InvariantCulture, $"  line {line}");
        }
        return sb.ToString();
    }

    /// <summary>Seconds as m:ss or h:mm:ss.</summary>
    internal static string Duration(double seconds)
    {
        var span = TimeSpan.FromSeconds(Math.Min(seconds, TimeSpan.MaxValue.TotalSeconds / 2));
        return span.TotalHours >= 1
            ? string.Create(CultureInfo.InvariantCulture, $"{(int)span.TotalHours}:{span.Minutes:00}:{span.Seconds:00}")
            : string.Create(CultureInfo.InvariantCulture, $"{span.Minutes}:{span.Seconds:00}");
    }
}

using System.Globalization;
using System.Text.Json;

namespace Machina.Benchmarks;

/// <summary>Prints measurements as aligned text tables or as one JSON object per line.</summary>
internal static class Report
{
    private static readonly CultureInfo Inv = CultureInfo.InvariantCulture;

    /// <summary>One JSON object, on one line, for a measurement.</summary>
    public static string Json(Measurement m, string table)
    {
        var record = new Dictionary<string, object?>
        {
            ["table"] = table,
            ["scenario"] = m.Scenario,
            ["title"] = m.Title,
            ["unit"] = m.Unit,
            ["size"] = m.Size,
            ["status"] = m.Status,
            ["runs"] = m.Runs,
            ["medianSeconds"] = m.MedianSeconds,
            ["minSeconds"] = m.MinSeconds,
            ["maxSeconds"] = m.MaxSeconds,
            ["cpuSeconds"] = m.CpuSeconds,
            ["jitCpuSeconds"] = m.JitSeconds,
            ["cpuSecondsWithoutJit"] = m.CpuWithoutJitSeconds,
            ["jitMethods"] = m.JitMethods,
            ["warmups"] = m.Warmups,
            ["jitSettled"] = m.JitSettled,
            ["repeatedRuns"] = m.RepeatedRuns,
            ["gcCollections"] = m.Collections,
            ["gcPauseSeconds"] = m.GcPauseSeconds,
            ["pageFaults"] = m.PageFaults,
            ["nsPerUnit"] = m.NanosecondsPerUnit,
            ["cpuNsPerUnit"] = m.CpuNanosecondsPerUnit,
            ["unitsPerSecond"] = m.UnitsPerSecond,
            ["allocatedBytes"] = m.AllocatedBytes,
            ["allocatedBytesPerUnit"] = m.BytesPerUnit,
            ["retainedBytes"] = m.RetainedBytes,
            ["peakBytes"] = m.PeakBytes,
            ["target"] = m.Target?.Text,
            ["targetNsPerUnit"] = m.Target?.NanosecondsPerUnit,
            ["targetBytesPerUnit"] = m.Target?.BytesPerUnit,
            ["timeRatio"] = m.TimeRatio,
            ["allocationRatio"] = m.AllocationRatio,
            ["note"] = m.Note,
        };
        return JsonSerializer.Serialize(record, JsonOptions);
    }

    /// <summary>Compact JSON that keeps characters such as &lt; readable.</summary>
    public static readonly JsonSerializerOptions JsonOptions = new() { Encoder = System.Text.Encodings.Web.JavaScriptEncoder.UnsafeRelaxedJsonEscaping };

    /// <summary>The results table: one row per scenario at its size, with the ratio to the target (at most 1 means met).</summary>
    public static string Results(IReadOnlyList<Measurement> rows)
    {
        string[] header = ["scenario", "size", "median", "min", "cpu", "jit cpu", "gc pause", "gc 0/1/2", "faults", "per unit", "cpu/unit", "-jit", "rate /s", "alloc/unit", "peak heap", "retained", "target", "ratio", "status"];
        var lines = rows.Select(m => m.Runs == 0
            ? new[] { m.Scenario, Count(m.Size), "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", "-", m.Target?.Text ?? "-", "-", $"{m.Status}: {m.Note}" }
            : [
                m.Scenario, Count(m.Size), Time(m.MedianSeconds), Time(m.MinSeconds), Time(m.CpuSeconds), Jit(m), Time(m.GcPauseSeconds), m.Collections, Count(m.PageFaults), Time(m.NanosecondsPerUnit / 1e9), Time(m.CpuNanosecondsPerUnit / 1e9), Time(m.CpuWithoutJitNanosecondsPerUnit / 1e9), Count(m.UnitsPerSecond),
                Bytes(m.BytesPerUnit), Bytes(m.PeakBytes), Bytes(m.RetainedBytes), m.Target?.Text ?? "-", Ratio(m), m.Status,
            ]).ToList();
        return Table(header, lines);
    }

    /// <summary>The scaling table: time per unit at each size and how much it grows (1.0 means perfectly linear).</summary>
    public static string Scaling(IReadOnlyList<Measurement> rows)
    {
        var sizes = rows.Where(m => m.Runs > 0).Select(m => m.Size).Distinct().Order().ToList();
        var header = new List<string> { "scenario" };
        header.AddRange(sizes.Select(s => $"{Count(s)}: per unit"));
        header.AddRange(sizes.Select(s => $"{Count(s)}: alloc/unit"));
        header.Add("growth");
        var lines = new List<string[]>();
        foreach (var group in rows.GroupBy(m => m.Scenario))
        {
            var bySize = group.Where(m => m.Runs > 0).ToDictionary(m => m.Size);
            if (bySize.Count == 0)
            {
                continue;
            }
            var line = new List<string> { group.Key };
            line.AddRange(sizes.Select(s => bySize.TryGetValue(s, out var m) ? Time(m.NanosecondsPerUnit / 1e9) : "-"));
            line.AddRange(sizes.Select(s => bySize.TryGetValue(s, out var m) ? Bytes(m.BytesPerUnit) : "-"));
            var measured = bySize.Values.OrderBy(m => m.Size).ToList();
            line.Add(measured.Count > 1
                ? (measured[^1].NanosecondsPerUnit / measured[0].NanosecondsPerUnit).ToString("0.00", Inv) + "x"
                : "-");
            lines.Add([.. line]);
        }
        return Table([.. header], lines);
    }

    /// <summary>The JIT's processor time in the median run, marked "(busy)" when a run the row keeps still compiled methods.</summary>
    private static string Jit(Measurement m) => Time(m.JitSeconds) + (m.JitSettled ? "" : " (busy)");

    private static string Ratio(Measurement m)
    {
        if (m.TimeRatio is not double time)
        {
            return "-";
        }
        string text = time.ToString("0.00", Inv);
        return m.AllocationRatio is double alloc ? $"{text} / {alloc.ToString("0.00", Inv)} mem" : text;
    }

    public static string Time(double seconds) => seconds switch
    {
        >= 1 => seconds.ToString("0.00", Inv) + " s",
        >= 1e-3 => (seconds * 1e3).ToString("0.0", Inv) + " ms",
        >= 1e-6 => (seconds * 1e6).ToString("0.00", Inv) + " us",
        _ => (seconds * 1e9).ToString("0", Inv) + " ns",
    };

    public static string Bytes(double bytes) => bytes switch
    {
        >= 1 << 30 => (bytes / (1 << 30)).ToString("0.00", Inv) + " GB",
        >= 1 << 20 => (bytes / (1 << 20)).ToString("0.0", Inv) + " MB",
        >= 1 << 10 => (bytes / (1 << 10)).ToString("0.0", Inv) + " KB",
        _ => bytes.ToString("0", Inv) + " B",
    };

    public static string Count(double n) => n.ToString("N0", Inv);

    public static string Table(string[] header, List<string[]> lines)
    {
        int[] widths = header.Select((h, i) => Math.Max(h.Length, lines.Select(l => l[i].Length).DefaultIfEmpty(0).Max())).ToArray();
        string Row(string[] cells) => "| " + string.Join(" | ", cells.Select((c, i) => i == 0 || i == cells.Length - 1 ? c.PadRight(widths[i]) : c.PadLeft(widths[i]))) + " |";
        var text = new List<string> { Row(header), "|" + string.Join("|", widths.Select((w, i) => i == 0 ? new string('-', w + 2) : new string('-', w + 1) + ":")) + "|" };
        text.AddRange(lines.Select(Row));
        return string.Join(Environment.NewLine, text);
    }
}

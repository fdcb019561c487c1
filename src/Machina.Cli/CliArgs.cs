using System.Globalization;

namespace Machina.Cli;

/// <summary>
/// The arguments of one command, read by hand: positionals, options with a value (<c>--out DIR</c> or <c>--out=DIR</c>) and
/// flags (<c>--sim</c>). Anything unknown is a <see cref="UsageException"/> that names the command's help.
/// </summary>
internal sealed class CliArgs
{
    private readonly string _command;
    private readonly Dictionary<string, string> _values = new(StringComparer.Ordinal);
    private readonly HashSet<string> _flags = new(StringComparer.Ordinal);
    private readonly Dictionary<string, List<string>> _repeated = new(StringComparer.Ordinal);

    /// <summary>The options that may be given more than once (each value kept, in order): <c>--load TASK=PATH</c> of <c>machina sim abb</c>.</summary>
    private static readonly HashSet<string> Repeatable = new(["--load", "--signal", "--task-type"], StringComparer.Ordinal);

    private CliArgs(string command) => _command = command;

    /// <summary>Arguments that are not options, in order.</summary>
    internal List<string> Positionals { get; } = [];

    /// <summary>
    /// Reads <paramref name="args"/> for <paramref name="command"/>, which knows the options <paramref name="options"/> (each takes a
    /// value) and the flags <paramref name="flags"/>. A lone "-" is a positional (standard input); "--" ends the options.
    /// </summary>
    internal static CliArgs Parse(string command, IReadOnlyList<string> args, IReadOnlyCollection<string> options, IReadOnlyCollection<string> flags)
    {
        var parsed = new CliArgs(command);
        bool optionsEnded = false;
        for (int i = 0; i < args.Count; i++)
        {
            string arg = args[i];
            if (optionsEnded || arg == "-" || !arg.StartsWith('-'))
            {
                parsed.Positionals.Add(arg);
                continue;
            }
            if (arg == "--")
            {
                optionsEnded = true;
                continue;
            }
            string name = arg;
            string? inline = null;
            int eq = arg.IndexOf('=', StringComparison.Ordinal);
            if (arg.StartsWith("--", StringComparison.Ordinal) && eq > 0)
            {
                name = arg[..eq];
                inline = arg[(eq + 1)..];
            }
            if (options.Contains(name))
            {
                string? value = inline ?? (i + 1 < args.Count ? args[++i] : null);
                if (value is null || (inline is null && value.StartsWith("--", StringComparison.Ordinal)))
                {
                    throw new UsageException($"{name} needs a value, e.g. {name} {Example(name)}. See: machina {command} --help");
                }
                if (Repeatable.Contains(name))
                {
                    (parsed._repeated.TryGetValue(name, out List<string>? all) ? all : parsed._repeated[name] = []).Add(value);
                    parsed._values.TryAdd(name, value);
                }
                else if (!parsed._values.TryAdd(name, value))
                {
                    throw new UsageException($"{name} is given twice. See: machina {command} --help");
                }
            }
            else if (flags.Contains(name) && inline is null)
            {
                parsed._flags.Add(name);
            }
            else
            {
                string? close = options.Concat(flags).FirstOrDefault(o => Close(o, name));
                throw new UsageException($"\"{arg}\" is not an option of machina {command}." +
                    (close is not null ? $" Did you mean {close}?" : "") + $" See: machina {command} --help");
            }
        }
        return parsed;
    }

    /// <summary>Every value of a repeatable option, in the order given (empty when it was not given).</summary>
    internal IReadOnlyList<string> Values(string name) => _repeated.TryGetValue(name, out List<string>? all) ? all : [];

    /// <summary>The value of an option, or null when it was not given.</summary>
    internal string? Value(string name) => _values.GetValueOrDefault(name);

    /// <summary>True when the flag was given.</summary>
    internal bool Has(string flag) => _flags.Contains(flag);

    /// <summary>True when the option was given.</summary>
    internal bool HasValue(string name) => _values.ContainsKey(name);

    /// <summary>The one positional argument, named <paramref name="what"/> in the error when it is missing or repeated.</summary>
    internal string Single(string what)
    {
        if (Positionals.Count == 1)
        {
            return Positionals[0];
        }
        throw new UsageException(Positionals.Count == 0
            ? $"machina {_command} needs {what}. See: machina {_command} --help"
            : $"machina {_command} takes one {what}, but was given {Positionals.Count}: {string.Join(" ", Positionals)}. See: machina {_command} --help");
    }

    /// <summary>Fails when there are positional arguments (for commands that take none).</summary>
    internal void NoPositionals()
    {
        if (Positionals.Count > 0)
        {
            throw new UsageException($"machina {_command} does not take \"{Positionals[0]}\". See: machina {_command} --help");
        }
    }

    /// <summary>The option's value, which must be given.</summary>
    internal string Required(string name, string hint) =>
        Value(name) ?? throw new UsageException($"machina {_command} needs {name} {hint}. See: machina {_command} --help");

    /// <summary>A TCP port (1–65535, or 0 when <paramref name="allowZero"/>: the system chooses), or <paramref name="fallback"/>.</summary>
    internal int Port(string name, int fallback, bool allowZero = false)
    {
        string? text = Value(name);
        if (text is null)
        {
            return fallback;
        }
        if (int.TryParse(text, NumberStyles.None, CultureInfo.InvariantCulture, out int port) && port <= 65535 && (port > 0 || allowZero))
        {
            return port;
        }
        throw new UsageException($"{name} must be a port number from {(allowZero ? 0 : 1)} to 65535, not \"{text}\".");
    }

    /// <summary>A positive finite number, or <paramref name="fallback"/>.</summary>
    internal double Positive(string name, double fallback)
    {
        string? text = Value(name);
        if (text is null)
        {
            return fallback;
        }
        if (double.TryParse(text, NumberStyles.Float, CultureInfo.InvariantCulture, out double value) && double.IsFinite(value) && value > 0)
        {
            return value;
        }
        throw new UsageException($"{name} must be a number greater than 0 (like 2 or 0.5), not \"{text}\".");
    }

    private static string Example(string option) => option switch
    {
        "--brand" => BrandRegistry.DefaultOnline.Name,
        "--out" => "out",
        "--model" => "\"IRB 120\"",
        "--host" => "192.168.125.1",
        "--port" => "7000",
        "--bind" => "127.0.0.1",
        "--speed-factor" => "10",
        _ => "VALUE",
    };

    private static bool Close(string known, string given)
    {
        string a = known.TrimStart('-'), b = given.TrimStart('-');
        return b.Length >= 2 && (a.StartsWith(b, StringComparison.OrdinalIgnoreCase) || string.Equals(a, b, StringComparison.OrdinalIgnoreCase)
            || Distance(a, b) <= 2);
    }

    private static int Distance(string a, string b)
    {
        var d = new int[a.Length + 1, b.Length + 1];
        for (int i = 0; i <= a.Length; i++) { d[i, 0] = i; }
        for (int j = 0; j <= b.Length; j++) { d[0, j] = j; }
        for (int i = 1; i <= a.Length; i++)
        {
            for (int j = 1; j <= b.Length; j++)
            {
                int cost = char.ToLowerInvariant(a[i - 1]) == char.ToLowerInvariant(b[j - 1]) ? 0 : 1;
                d[i, j] = Math.Min(Math.Min(d[i - 1, j] + 1, d[i, j - 1] + 1), d[i - 1, j - 1] + cost);
            }
        }
        return d[a.Length, b.Length];
    }
}

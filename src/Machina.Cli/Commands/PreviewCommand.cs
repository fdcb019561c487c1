using Machina.Cli.Preview;
using Machina.Cli.Programs;

namespace Machina.Cli.Commands;

/// <summary><c>machina preview</c>: a picture of a program's tool path, as SVG (three views) or HTML (interactive 3D).</summary>
internal static class PreviewCommand
{
    internal static readonly CliCommand Command = new(
        "preview",
        "Draw a program's tool path: three views (SVG) or interactive 3D (HTML)",
        $"""
        Usage: machina preview PROGRAM --out FILE.svg|FILE.html [--brand B] [--model M]

        Draws where the tool tip of PROGRAM (a text file of Machina instructions, - for standard input) goes.
          FILE.svg    top, front and side views at one scale, with a grid and a legend (opens in any browser)
          FILE.html   one self-contained page with a 3D view to turn, move and zoom (no internet needed)
        Linear, joint and arc moves have their own colours; for 3D printers (--brand zmorph or marlin) and while
        extruding, travel and extrusion moves. Start and end are marked, and warnings are drawn where they happen
        with their line number: instructions that cannot be applied and, with --model, every kinematic problem.

        Options:
          --out FILE   the picture to write; .svg or .html decides the kind
          --brand B    {Brands.Choices(Brands.All)} (printers draw travel and extrusion; default: an arm)
          --model M    the arm model, e.g. "IRB 120": the arm is drawn at the start and the end (and where the first
                       warnings are), and kinematic problems become warnings on the picture

        Examples:
          machina preview square.machina --out square.svg
          machina preview square.machina --model "IRB 120" --out square.html
        """,
        Options: ["--out", "--brand", "--model"],
        Flags: [],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        string path = args.Single("a PROGRAM file (or - for standard input)");
        string output = args.Required("--out", "FILE.svg or FILE.html");
        string extension = Path.GetExtension(output).ToLowerInvariant();
        if (extension is not (".svg" or ".html" or ".htm"))
        {
            throw new UsageException($"--out must end in .svg (three views) or .html (interactive 3D), not \"{output}\".");
        }
        RobotType? brand = args.Value("--brand") is string b ? Brands.Parse(b, Brands.All) : null;
        RobotModel? model = Brands.Model(args.Value("--model"), brand);
        bool printer = brand is RobotType t && Brands.IsPrinter(t);
        using ProgramReader reader = ProgramReader.Open(path, context, null);
        PreviewPath preview = PreviewPath.Build(reader, model, printer, context.Cancellation);
        string title = $"Tool path of {Path.GetFileName(reader.DisplayName)}";
        string device = model is not null ? $"{model.Brand} {model.Name}" : brand is RobotType known ? known.ToString() : "robot arm (no model)";
        string subtitle = $"{device} · {Counted.Of(preview.Actions, "action")} · {Counted.Of(preview.Segments.Count, "move")} · {preview.Warnings.Count} warning{(preview.Warnings.Count == 1 ? "" : "s")} · about {CycleTime.Short(preview.CycleTime.TotalSeconds)} · units: mm";
        string text = extension == ".svg" ? SvgWriter.Write(preview, title, subtitle) : HtmlWriter.Write(preview, title, subtitle);
        string full = context.FullPath(output);
        string? folder = Path.GetDirectoryName(full);
        if (!string.IsNullOrEmpty(folder))
        {
            Directory.CreateDirectory(folder);
        }
        await File.WriteAllTextAsync(full, text, context.Cancellation).ConfigureAwait(false);
        await context.Stdout.WriteLineAsync(CompileCommand.Display(full, context)).ConfigureAwait(false);
        await context.Stdout.WriteLineAsync(preview.CycleTime.ToText(model is not null ? $"the {model.Brand} {model.Name}" : "a generic controller (no --model)", model)).ConfigureAwait(false);
        foreach (PathWarning warning in preview.Warnings)
        {
            await context.Stderr.WriteLineAsync($"{reader.DisplayName}:{warning.Line}:{warning.Column}: warning: {warning.Instruction} {warning.Message}").ConfigureAwait(false);
        }
        if (preview.Targets.Count == 0)
        {
            await context.Stderr.WriteLineAsync("machina: warning: the program never gives an absolute position (MoveTo, TransformTo, or AxesTo with --model), so there is no path to draw.").ConfigureAwait(false);
        }
        return ExitCodes.Ok;
    }
}

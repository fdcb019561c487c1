using System.Globalization;
using System.Text;

namespace Machina.Cli.Commands;

/// <summary><c>machina models</c>: the catalogue of robot arm models, or the details of one.</summary>
internal static class ModelsCommand
{
    internal static readonly CliCommand Command = new(
        "models",
        "List the robot arm models Machina knows (for --model)",
        """
        Usage: machina models [NAME] [--brand abb|ur|kuka]

        Lists the robot arm models of Machina's catalogue, with their joint ranges. With a NAME, shows that model in
        detail: joint limits and maximum speeds, geometry, and the public documents the numbers come from.
        Give a model to compile, check, preview, run or sim with --model NAME (quote names with spaces: --model "IRB 120").

        Examples:
          machina models
          machina models --brand ur
          machina models "IRB 120"
        """,
        Options: ["--brand"],
        Flags: [],
        RunAsync);

    private static async Task<int> RunAsync(CliArgs args, CliContext context)
    {
        if (args.Positionals.Count > 1)
        {
            throw new UsageException($"machina models takes at most one model name; quote names with spaces: machina models \"{string.Join(" ", args.Positionals)}\"");
        }
        if (args.Positionals.Count == 1)
        {
            RobotModel model = Brands.Model(args.Positionals[0], null)!;
            await context.Stdout.WriteAsync(Details(model)).ConfigureAwait(false);
            return ExitCodes.Ok;
        }
        string? brand = args.Value("--brand") is string b ? BrandRegistry.For(Brands.Parse(b, Brands.Online)).ModelBrand : null;
        var models = RobotModels.All.Where(m => brand is null || m.Brand == brand).ToList();
        await context.Stdout.WriteAsync(Table(models)).ConfigureAwait(false);
        return ExitCodes.Ok;
    }

    /// <summary>One line per model: name, brand, geometry family and joint ranges.</summary>
    internal static string Table(IReadOnlyList<RobotModel> models)
    {
        int width = Math.Max(5, models.Select(m => m.Name.Length).DefaultIfEmpty(0).Max());
        var sb = new StringBuilder();
        sb.AppendLine(CultureInfo.InvariantCulture, $"{"MODEL".PadRight(width)}  BRAND  JOINT RANGES (degrees, axes 1-6)");
        foreach (RobotModel m in models)
        {
            var ranges = Enumerable.Range(0, Joints.Count).Select(i => $"{G(m.MinJoints[i])}..{G(m.MaxJoints[i])}");
            sb.AppendLine(CultureInfo.InvariantCulture, $"{m.Name.PadRight(width)}  {m.Brand,-5}  {string.Join("  ", ranges)}");
        }
        sb.AppendLine(CultureInfo.InvariantCulture, $"{models.Count} models. Details: machina models \"NAME\". Use one with --model \"NAME\".");
        return sb.ToString();
    }

    /// <summary>Everything about one model.</summary>
    internal static string Details(RobotModel m)
    {
        var sb = new StringBuilder();
        sb.AppendLine(CultureInfo.InvariantCulture, $"{m.Name} ({m.Brand}, {m.Family} kinematics)");
        sb.AppendLine("  axis     min      max   max speed");
        for (int i = 0; i < Joints.Count; i++)
        {
            string speed = m.MaxJointSpeeds is Joints s ? $"{G(s[i])} deg/s" : "not published";
            sb.AppendLine(CultureInfo.InvariantCulture, $"  {i + 1,4} {G(m.MinJoints[i]),7}° {G(m.MaxJoints[i]),7}°   {speed}");
        }
        if (m.Opw is OpwParameters o)
        {
            sb.AppendLine(CultureInfo.InvariantCulture, $"  geometry (OPW, mm): a1 {G(o.A1)}, a2 {G(o.A2)}, b {G(o.B)}, c1 {G(o.C1)}, c2 {G(o.C2)}, c3 {G(o.C3)}, c4 {G(o.C4)}");
        }
        if (m.UniversalRobotsDh is UniversalRobotsDh d)
        {
            sb.AppendLine(CultureInfo.InvariantCulture, $"  geometry (DH, mm): d1 {G(d.D1)}, a2 {G(d.A2)}, a3 {G(d.A3)}, d4 {G(d.D4)}, d5 {G(d.D5)}, d6 {G(d.D6)}");
        }
        sb.AppendLine("  source: " + m.Source);
        return sb.ToString();
    }

    private static string G(double value) => value.ToString("0.###", CultureInfo.InvariantCulture);
}

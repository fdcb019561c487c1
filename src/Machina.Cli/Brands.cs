namespace Machina.Cli;

/// <summary>Brand names as typed on the command line: those of the library's <see cref="BrandRegistry"/> (abb, ur, kuka, zmorph…).</summary>
internal static class Brands
{
    /// <summary>Every brand a program can be compiled for, in the order the help lists them.</summary>
    internal static readonly RobotType[] All = [.. BrandRegistry.All.Select(b => b.Type)];

    /// <summary>Every brand that can be controlled online (the arms with a driver), in the order the help lists them.</summary>
    internal static readonly RobotType[] Online = [.. BrandRegistry.Online.Select(b => b.Type)];

    /// <summary>"abb|ur|kuka|…" for usage lines.</summary>
    internal static string Choices(IEnumerable<RobotType> brands) => string.Join("|", brands.Select(Name));

    /// <summary>The lower-case name of a brand.</summary>
    internal static string Name(RobotType brand) => BrandRegistry.For(brand).Name;

    /// <summary>The brand named <paramref name="text"/> (any letter case), which must be one of <paramref name="allowed"/>.</summary>
    internal static RobotType Parse(string text, IReadOnlyCollection<RobotType> allowed, string option = "--brand")
    {
        if (BrandRegistry.Find(text) is BrandDefinition named && allowed.Contains(named.Type))
        {
            return named.Type;
        }
        throw new UsageException($"\"{text}\" is not a brand {option} accepts here; use one of: {string.Join(", ", allowed.Select(Name))}.");
    }

    /// <summary>True for the arm brands that can take a robot model (ABB, UR, KUKA).</summary>
    internal static bool IsArm(RobotType brand) => BrandRegistry.For(brand).IsArm;

    /// <summary>True for 3D printers.</summary>
    internal static bool IsPrinter(RobotType brand) => BrandRegistry.For(brand).Kind == BrandKind.Printer;

    /// <summary>
    /// The catalogue model named <paramref name="name"/>, checked against <paramref name="brand"/> the way <c>Robot.SetModel</c> checks it
    /// (a printer takes no arm model; a UR program needs a UR model). Null when no name was given.
    /// </summary>
    internal static RobotModel? Model(string? name, RobotType? brand)
    {
        if (name is null)
        {
            return null;
        }
        RobotModel model;
        try
        {
            model = RobotModels.Get(name);
        }
        catch (ArgumentException ex)
        {
            throw new UsageException(FirstSentences(ex.Message) + " Run \"machina models\" to list them.");
        }
        if (brand is RobotType b && BrandRegistry.For(b).Kind != BrandKind.Listing)
        {
            try
            {
                Robot.Create("Check", b, model);
            }
            catch (ArgumentException ex)
            {
                throw new UsageException(FirstSentences(ex.Message));
            }
        }
        return model;
    }

    /// <summary>An exception message without the "(Parameter 'x')" tail .NET appends.</summary>
    internal static string FirstSentences(string message)
    {
        int paren = message.IndexOf(" (Parameter '", StringComparison.Ordinal);
        return paren > 0 ? message[..paren] : message;
    }
}

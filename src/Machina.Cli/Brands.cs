namespace Machina.Cli;

/// <summary>Brand names as typed on the command line (abb, ur, kuka, zmorph, marlin, human, machina).</summary>
internal static class Brands
{
    /// <summary>Every brand a program can be compiled for, in the order the help lists them.</summary>
    internal static readonly RobotType[] All = [RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA];

    /// <summary>"abb|ur|kuka|…" for usage lines.</summary>
    internal static string Choices(IEnumerable<RobotType> brands) => string.Join("|", brands.Select(Name));

    /// <summary>The lower-case name of a brand.</summary>
    internal static string Name(RobotType brand) => brand.ToString().ToLowerInvariant();

    /// <summary>The brand named <paramref name="text"/> (any letter case), which must be one of <paramref name="allowed"/>.</summary>
    internal static RobotType Parse(string text, IReadOnlyCollection<RobotType> allowed, string option = "--brand")
    {
        foreach (RobotType brand in allowed)
        {
            if (string.Equals(text.Trim(), brand.ToString(), StringComparison.OrdinalIgnoreCase))
            {
                return brand;
            }
        }
        throw new UsageException($"\"{text}\" is not a brand {option} accepts here; use one of: {string.Join(", ", allowed.Select(Name))}.");
    }

    /// <summary>True for the arm brands that can take a robot model (ABB, UR, KUKA).</summary>
    internal static bool IsArm(RobotType brand) => brand is RobotType.ABB or RobotType.UR or RobotType.KUKA;

    /// <summary>True for 3D printers.</summary>
    internal static bool IsPrinter(RobotType brand) => brand is RobotType.ZMORPH or RobotType.MARLIN;

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
        if (brand is RobotType b && b != RobotType.HUMAN && b != RobotType.MACHINA)
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

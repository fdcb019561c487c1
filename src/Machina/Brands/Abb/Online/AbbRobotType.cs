namespace Machina;

/// <summary>
/// The arm an ABB controller runs, as RAPID's <c>GetSysInfo(\RobotType)</c> and Robot Web Services name it ("IRB 120-3/0.6",
/// "IRB 1200-5/0.9", "IRB 140T-5/0.8 Type C"): the catalogue model of that exact name, or of its family when the catalogue
/// lists the family without variants (IRB 120-3/0.6 is the IRB 120). Anything else is unknown: no guess between variants.
/// </summary>
internal static class AbbRobotType
{
    /// <summary>The information request's first value that asks for the robot type (1 = version, 2 = address).</summary>
    public const int InformationCode = 3;

    /// <summary>The catalogue model the controller's robot type names, or null.</summary>
    public static RobotModel? Find(string robotType)
    {
        ArgumentNullException.ThrowIfNull(robotType);
        string name = robotType.Trim();
        int type = name.IndexOf(" Type ", StringComparison.OrdinalIgnoreCase);
        if (type > 0)
        {
            name = name[..type].TrimEnd();   // "Type A/B/C": a revision of the same arm
        }
        if (name.Length == 0)
        {
            return null;
        }
        RobotModel? exact = RobotModels.Find(name);
        if (exact is not null)
        {
            return exact.Brand == "ABB" ? exact : null;
        }
        int dash = name.IndexOf('-', StringComparison.Ordinal);
        if (dash <= 0)
        {
            return null;
        }
        // Only a family the catalogue lists as one arm (IRB 120, IRB 140): a family with variants (IRB 1600-6/1.2, -8/1.45) stays unknown.
        string family = name[..dash].TrimEnd();
        RobotModel? model = RobotModels.Find(family);
        bool variants = RobotModels.All.Any(m => m.Name.StartsWith(family + "-", StringComparison.OrdinalIgnoreCase));
        return model is not null && model.Brand == "ABB" && !variants ? model : null;
    }
}

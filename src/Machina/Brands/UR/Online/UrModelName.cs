using System.Globalization;

namespace Machina;

/// <summary>
/// The arm a UR controller runs, from two dashboard answers: <c>get robot model</c> ("UR3", "UR5", "UR10", "UR16", "UR20"…,
/// without the e-Series "e") and <c>PolyscopeVersion</c> ("URSoftware 5.11.1.108318 (Jul 06 2021)"): software 5 and later
/// runs e-Series arms, 3 and earlier CB-Series arms.
/// </summary>
internal static class UrModelName
{
    /// <summary>The catalogue model for these answers, or null when there is none or the answers leave it open (UR5 or UR5e).</summary>
    public static RobotModel? Find(string model, string? software)
    {
        ArgumentNullException.ThrowIfNull(model);
        string name = model.Trim();
        if (name.Length == 0)
        {
            return null;
        }
        int? major = SoftwareMajor(software);
        RobotModel? plain = RobotModels.Find(name);
        RobotModel? eSeries = name.EndsWith('e') ? null : RobotModels.Find(name + "e");
        if (plain is not null && plain.Brand != "UR" || eSeries is not null && eSeries.Brand != "UR")
        {
            return null;
        }
        return major switch
        {
            >= 5 => eSeries ?? plain,
            not null => plain,
            // Without the software version a name with both generations (UR5 and UR5e) stays open: their arms differ.
            null => eSeries is null ? plain : plain is null ? eSeries : null,
        };
    }

    /// <summary>The major version in a <c>PolyscopeVersion</c> answer, or null when it has none.</summary>
    internal static int? SoftwareMajor(string? software)
    {
        if (software is null)
        {
            return null;
        }
        foreach (string word in software.Split(' ', StringSplitOptions.RemoveEmptyEntries))
        {
            int dot = word.IndexOf('.', StringComparison.Ordinal);
            if (dot > 0 && int.TryParse(word.AsSpan(0, dot), NumberStyles.None, CultureInfo.InvariantCulture, out int major))
            {
                return major;
            }
        }
        return null;
    }
}

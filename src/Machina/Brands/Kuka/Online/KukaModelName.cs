using System.Text.RegularExpressions;

namespace Machina;

/// <summary>
/// The arm a KUKA controller runs, from its <c>$MODEL_NAME[]</c> ("#KR6R900SIXX C4", "#KR16_2 C4 FLR"): without the '#', with
/// '_' read as a space, and without the words that name the controller or its mounting options (C4, C4SR, C4FLR, KRC4, FLR,
/// SR, CR), the rest must be a catalogue name (spaces, dashes and case ignored). Anything else is unknown: no guess.
/// </summary>
internal static partial class KukaModelName
{
    [GeneratedRegex(@"^(KR)?C\d+[A-Z]*$|^(FLR|SR|CR|COMPACT)$", RegexOptions.IgnoreCase | RegexOptions.CultureInvariant)]
    private static partial Regex ControllerWord();

    /// <summary>The catalogue model <paramref name="modelName"/> names, or null.</summary>
    public static RobotModel? Find(string modelName)
    {
        ArgumentNullException.ThrowIfNull(modelName);
        string[] words = modelName.Trim().TrimStart('#').Replace('_', ' ')
            .Split(' ', StringSplitOptions.RemoveEmptyEntries | StringSplitOptions.TrimEntries);
        string arm = string.Join(' ', words.Where(w => !ControllerWord().IsMatch(w)));
        if (arm.Length == 0)
        {
            return null;
        }
        RobotModel? model = RobotModels.Find(arm);
        return model is not null && model.Brand == "KUKA" ? model : null;
    }
}

namespace Machina.Tests.Docs;

/// <summary>
/// The examples of docs/reference.md, one method per verb, named after it. <see cref="ReferenceDocTests"/> checks that each
/// method's body is, line for line, the example printed in the verb's section, runs it after <see cref="Preamble"/> on a
/// robot of every brand, and checks the native lines printed under it against what the compilers and encoders produce.
/// </summary>
internal static class ReferenceExamples
{
    /// <summary>What every example starts from: a known position (and the default orientation, tool pointing down).</summary>
    internal static void Preamble(Robot bot)
    {
        bot.MoveTo(400, 300, 500);
    }

    internal static void Move(Robot bot)
    {
        bot.Move(0, 0, 50);
    }

    internal static void MoveTo(Robot bot)
    {
        bot.MoveTo(300, 200, 400);
    }

    internal static void Rotate(Robot bot)
    {
        bot.Rotate(0, 0, 1, 45);
    }

    internal static void RotateTo(Robot bot)
    {
        bot.RotateTo(0, 1, 0, 1, 0, 0);
    }

    internal static void Transform(Robot bot)
    {
        bot.Transform(new Vector(0, 0, 50), Rotation.FromAxisAngle(0, 0, 1, 90));
    }

    internal static void TransformTo(Robot bot)
    {
        bot.TransformTo(300, 0, 400, -1, 0, 0, 0, 1, 0);
    }

    internal static void ArcMotion(Robot bot)
    {
        bot.ArcMotion(50, 50, 0, 100, 0, 0);
    }

    internal static void ArcMotionTo(Robot bot)
    {
        bot.ArcMotionTo(450, 350, 500, 500, 300, 500);
    }

    internal static void Axes(Robot bot)
    {
        bot.AxesTo(0, 0, 0, 0, 90, 0);
        bot.Axes(30, 0, 0, 0, 0, 0);
    }

    internal static void AxesTo(Robot bot)
    {
        bot.AxesTo(0, 0, 0, 0, 90, 0);
    }

    internal static void ExternalAxis(Robot bot)
    {
        bot.ExternalAxisTo(1, 500);
        bot.ExternalAxis(1, 100);
        bot.Move(100, 0, 0);
    }

    internal static void ExternalAxisTo(Robot bot)
    {
        bot.ExternalAxisTo(1, 500);
        bot.Move(100, 0, 0);
    }

    internal static void ArmAngle(Robot bot)
    {
        bot.ArmAngleTo(30);
        bot.ArmAngle(10);
        bot.Move(0, 0, 10);
    }

    internal static void ArmAngleTo(Robot bot)
    {
        bot.ArmAngleTo(30);
        bot.Move(0, 0, 10);
    }

    internal static void Speed(Robot bot)
    {
        bot.Speed(30);
        bot.Move(0, 0, 50);
    }

    internal static void SpeedTo(Robot bot)
    {
        bot.SpeedTo(100);
        bot.Move(0, 0, 50);
    }

    internal static void Acceleration(Robot bot)
    {
        bot.Acceleration(470);
        bot.Move(0, 0, 50);
    }

    internal static void AccelerationTo(Robot bot)
    {
        bot.AccelerationTo(500);
        bot.Move(0, 0, 50);
    }

    internal static void Precision(Robot bot)
    {
        bot.Precision(5);
        bot.Move(0, 0, 50);
    }

    internal static void PrecisionTo(Robot bot)
    {
        bot.PrecisionTo(0);
        bot.Move(0, 0, 50);
    }

    internal static void MotionMode(Robot bot)
    {
        bot.MotionMode("joint");
        bot.Move(0, 0, 50);
    }

    internal static void Coordinates(Robot bot)
    {
        bot.Coordinates("local");
        bot.Move(0, 0, 50);
    }

    internal static void PushSettings(Robot bot)
    {
        bot.PushSettings();
        bot.SpeedTo(200);
        bot.Move(0, 0, 50);
    }

    internal static void PopSettings(Robot bot)
    {
        bot.PushSettings();
        bot.SpeedTo(200);
        bot.PopSettings();
        bot.Move(0, 0, 50);
    }

    internal static void Wait(Robot bot)
    {
        bot.Wait(1500);
    }

    internal static void Message(Robot bot)
    {
        bot.Message("Hello Robot!");
    }

    internal static void Comment(Robot bot)
    {
        bot.Comment("Start of the square");
    }

    internal static void CustomCode(Robot bot)
    {
        bot.CustomCode("TPErase;");
    }

    internal static void DefineTool(Robot bot)
    {
        bot.DefineTool("pen", new Vector(0, 0, 100), Rotation.Identity, 0.5, new Vector(0, 0, 40));
    }

    internal static void AttachTool(Robot bot)
    {
        bot.DefineTool("pen", new Vector(0, 0, 100), Rotation.Identity, 0.5, new Vector(0, 0, 40));
        bot.AttachTool("pen");
        bot.Move(0, 0, 50);
    }

    internal static void DetachTool(Robot bot)
    {
        bot.DefineTool("pen", new Vector(0, 0, 100), Rotation.Identity, 0.5, new Vector(0, 0, 40));
        bot.AttachTool("pen");
        bot.DetachTool();
    }

    internal static void WriteDigital(Robot bot)
    {
        bot.WriteDigital(1, true);
        bot.WriteDigital("DO_Gripper", false);
    }

    internal static void WaitForDigital(Robot bot)
    {
        bot.WaitForDigital(1, true);
        bot.WaitForDigital("DI_Part", false, 2500);
    }

    internal static void ReadDigital(Robot bot)
    {
        bot.ReadDigital(1);
        bot.ReadDigital("DI_Part");
    }

    internal static void ReadAnalog(Robot bot)
    {
        bot.ReadAnalog(1);
        bot.ReadAnalog("AI_Flow");
    }

    internal static void WriteAnalog(Robot bot)
    {
        bot.WriteAnalog(1, 0.5);
        bot.WriteAnalog("AO_Glue", 0.5);
    }

    internal static void Temperature(Robot bot)
    {
        bot.TemperatureTo(200, "extruder", false);
        bot.Temperature(10, "extruder");
    }

    internal static void TemperatureTo(Robot bot)
    {
        bot.TemperatureTo(60, "bed");
    }

    internal static void ExtrusionRate(Robot bot)
    {
        bot.ExtrusionRateTo(0.05);
        bot.ExtrusionRate(0.01);
        bot.Extrude();
        bot.Move(50, 0, 0);
    }

    internal static void ExtrusionRateTo(Robot bot)
    {
        bot.ExtrusionRateTo(0.05);
        bot.Extrude();
        bot.Move(50, 0, 0);
    }

    internal static void Extrude(Robot bot)
    {
        bot.ExtrusionRateTo(0.05);
        bot.Extrude();
        bot.Move(50, 0, 0);
        bot.Extrude(false);
        bot.Move(0, 50, 0);
    }

    internal static void Initialize(Robot bot)
    {
        bot.Initialize();
    }

    internal static void Terminate(Robot bot)
    {
        bot.Terminate();
    }
}

namespace Machina.Tests.Online;

/// <summary>How each brand's host maps the arm name its controller reports to a catalogue model, and refuses to guess.</summary>
public class ControllerModelNameTests
{
    [Theory]
    [InlineData("UR5", "URSoftware 5.11.1.108318 (Jul 06 2021)", "UR5e")]
    [InlineData("UR5", "URSoftware 3.15.7.106331 (Jan 31 2022)", "UR5")]
    [InlineData("UR10", "URSoftware 5.4.0.0", "UR10e")]
    [InlineData("UR3", "URSoftware 3.3.0.145", "UR3")]
    [InlineData("UR16", "URSoftware 5.9.0.0", "UR16e")]
    [InlineData("UR16", null, "UR16e")]
    [InlineData("UR20", "URSoftware 5.14.0.0", "UR20")]
    [InlineData("UR30", null, "UR30")]
    [InlineData(" UR5e ", null, "UR5e")]
    public void Ur_DashboardAnswers_CatalogueModel(string model, string? software, string expected)
    {
        Assert.Equal(expected, UrModelName.Find(model, software)?.Name);
    }

    [Theory]
    [InlineData("UR5", null)]                          // UR5 or UR5e: their arms differ, so no guess
    [InlineData("UR5", "could not parse")]
    [InlineData("UR99", "URSoftware 5.11.0.0")]
    [InlineData("", "URSoftware 5.11.0.0")]
    [InlineData("IRB 120", "URSoftware 5.11.0.0")]     // another brand's arm is not a UR's
    public void Ur_UnknownOrOpen_NoModel(string model, string? software)
    {
        Assert.Null(UrModelName.Find(model, software));
    }

    [Theory]
    [InlineData("IRB 120-3/0.6", "IRB 120")]
    [InlineData("IRB 1200-5/0.9", "IRB 1200-5/0.9")]
    [InlineData("IRB 1600-8/1.45", "IRB 1600-8/1.45")]
    [InlineData("IRB 140-6/0.8 Type C", "IRB 140")]
    [InlineData("irb 2600-20/1.65", "IRB 2600-20/1.65")]
    public void Abb_RobotType_CatalogueModel(string robotType, string expected)
    {
        Assert.Equal(expected, AbbRobotType.Find(robotType)?.Name);
    }

    [Theory]
    [InlineData("IRB 1600-10/1.2")]   // a family with variants in the catalogue: no guess between them
    [InlineData("IRB 910SC-3/0.65")]
    [InlineData("NONE")]
    [InlineData("")]
    [InlineData("KR 6 R900 sixx")]    // another brand's arm
    public void Abb_UnknownRobotType_NoModel(string robotType)
    {
        Assert.Null(AbbRobotType.Find(robotType));
    }

    [Theory]
    [InlineData("#KR6R900SIXX C4", "KR 6 R900 sixx")]
    [InlineData("#KR6 R700 SIXX C4SR", "KR 6 R700 sixx")]
    [InlineData("#KR16_2 C4 FLR", "KR 16-2")]
    [InlineData("#KR10 R1100-2 KRC4", "KR 10 R1100-2")]
    [InlineData("KR 240 R3330", "KR 240 R3330")]
    public void Kuka_ModelName_CatalogueModel(string modelName, string expected)
    {
        Assert.Equal(expected, KukaModelName.Find(modelName)?.Name);
    }

    [Theory]
    [InlineData("#KR1000 TITAN C4")]
    [InlineData("#KR6R900SIXX W C4")]   // a word that is not the controller's: no guess that it changes nothing
    [InlineData("# C4")]
    [InlineData("")]
    [InlineData("#UR5e")]
    public void Kuka_UnknownModelName_NoModel(string modelName)
    {
        Assert.Null(KukaModelName.Find(modelName));
    }
}

using Machina.Simulation;

namespace Machina.Tests.Brands.Registry;

/// <summary>The one list of brands (<see cref="BrandRegistry"/>) and the virtual controllers registered against it.</summary>
public sealed class BrandRegistryTests
{
    /// <summary>A token that ends the test's waits after 10 s.</summary>
    private static CancellationToken Timeout() => new CancellationTokenSource(TimeSpan.FromSeconds(10)).Token;

    [Fact]
    public void Registry_HasOneDefinitionPerRobotType_InTheHelpOrder()
    {
        Assert.Equal([RobotType.ABB, RobotType.UR, RobotType.KUKA, RobotType.ZMORPH, RobotType.MARLIN, RobotType.HUMAN, RobotType.MACHINA],
            BrandRegistry.All.Select(b => b.Type));
        Assert.Equal(Enum.GetValues<RobotType>().Order(), BrandRegistry.All.Select(b => b.Type).Order());
        Assert.Equal(["abb", "ur", "kuka", "zmorph", "marlin", "human", "machina"], BrandRegistry.All.Select(b => b.Name));
    }

    [Fact]
    public void For_GivesEachTypesOwnDefinition_TheSameObjectAsTheList()
    {
        foreach (RobotType type in Enum.GetValues<RobotType>())
        {
            BrandDefinition definition = BrandRegistry.For(type);
            Assert.Equal(type, definition.Type);
            Assert.Same(definition, BrandRegistry.TryFor(type));
            Assert.Same(definition, Assert.Single(BrandRegistry.All, b => b.Type == type));
        }
        Assert.Same(AbbBrand.Definition, BrandRegistry.For(RobotType.ABB));
        Assert.Same(MachinaTextBrand.Definition, BrandRegistry.For(RobotType.MACHINA));
        Assert.Null(BrandRegistry.TryFor((RobotType)99));
        ArgumentOutOfRangeException ex = Assert.Throws<ArgumentOutOfRangeException>(() => BrandRegistry.For((RobotType)99));
        Assert.StartsWith("Unknown robot brand.", ex.Message, StringComparison.Ordinal);
        Assert.Equal([RobotType.UR, RobotType.ABB, RobotType.KUKA], BrandRegistry.Catalogue.Select(b => b.Type));
        Assert.Same(UrBrand.Definition, BrandRegistry.Catalogue[0]);
    }

    [Fact]
    public void NamesAndAliases_AreUnique_AndFoundInAnyLetterCase()
    {
        string[] all = [.. BrandRegistry.All.SelectMany(b => b.Aliases.Append(b.Name)).Select(n => n.ToLowerInvariant())];

        Assert.Equal(all.Length, all.Distinct().Count());
        Assert.Same(UrBrand.Definition, BrandRegistry.Find(" Universal Robots "));
        Assert.Same(KukaBrand.Definition, BrandRegistry.Find("KUKA"));
        Assert.Null(BrandRegistry.Find("fanuc"));
    }

    [Fact]
    public void EachBrand_CompilesWithItsOwnCompiler()
    {
        foreach (BrandDefinition brand in BrandRegistry.All)
        {
            Assert.Equal(brand.Type, brand.CreateCompiler().Brand);
            Assert.Equal(brand.Type, Compilers.For(brand.Type).Brand);
        }
        ArgumentOutOfRangeException ex = Assert.Throws<ArgumentOutOfRangeException>(() => Compilers.For((RobotType)99));
        Assert.StartsWith("Unknown robot language.", ex.Message, StringComparison.Ordinal);
    }

    [Fact]
    public void OnlineBrands_AreTheArms_WithTheirDriverPortsAndInstructions()
    {
        Assert.Equal([RobotType.ABB, RobotType.UR, RobotType.KUKA], BrandRegistry.Online.Select(b => b.Type));
        Assert.All(BrandRegistry.Online, b => Assert.Equal(b.Type, b.Online!.Brand));
        Assert.Equal([7000, 30003, 7000], BrandRegistry.Online.Select(b => b.DefaultPort));
        Assert.Equal("MoveL", AbbBrand.Definition.InstructionName("@2 1 350 50 500 0 0 1 0;"));
        Assert.Equal("MoveL", UrBrand.Definition.InstructionName("2 1 3000 1000 4000 0 31416 0"));
        Assert.Equal("Linear", KukaBrand.Definition.InstructionName("<A ID=\"2\" T=\"1\" X=\"350\"/>"));
        Assert.Null(AbbBrand.Definition.InstructionName("hello"));
        Assert.Null(MarlinBrand.Definition.InstructionName("@2 1 350;"));
        Assert.Equal("ZMORPH robots cannot be controlled online; only ABB, UR and KUKA robots can. (Parameter 'brand')",
            Assert.Throws<ArgumentException>(() => OnlineBrands.For(RobotType.ZMORPH)).Message);
    }

    [Fact]
    public void Arms_TakeModelsOfTheirCatalogueBrand_PrintersNone()
    {
        Assert.Equal(["ABB", "UR", "KUKA", null, null, null, null], BrandRegistry.All.Select(b => b.ModelBrand));
        RobotModel ur5e = RobotModels.Get("UR5e");
        Assert.Equal("UR", RobotModel.FromUniversalRobotsDh("Mine", ur5e.UniversalRobotsDh!.Value, ur5e.MinJoints, ur5e.MaxJoints).Brand);
        RobotModel kr = RobotModels.Get("KR 6 R900 sixx");
        ArgumentException notOpw = Assert.Throws<ArgumentException>(() => RobotModel.FromOpw("Mine", "Universal Robots", kr.Opw!.Value, kr.MinJoints, kr.MaxJoints));
        Assert.Equal("OPW models follow ABB or KUKA joint conventions; brand must be \"ABB\" or \"KUKA\", not \"Universal Robots\". (Parameter 'brand')", notOpw.Message);
        Assert.Equal("KUKA", RobotModel.FromOpw("Mine", "kuka", kr.Opw!.Value, kr.MinJoints, kr.MaxJoints).Brand);
        Assert.True(KukaBrand.Definition.MirroredOpwJoints);
        Assert.False(AbbBrand.Definition.MirroredOpwJoints);
    }

    [Fact]
    public void VirtualControllers_AreTheOnlineArms_MovingLikeTheirBrandsDefaultModel()
    {
        Assert.Equal([RobotType.ABB, RobotType.UR, RobotType.KUKA], VirtualControllerRegistry.Brands);
        foreach (RobotType brand in VirtualControllerRegistry.Brands)
        {
            BrandDefinition definition = BrandRegistry.For(brand);
            RobotModel model = VirtualControllerRegistry.DefaultOptions(brand).Model!;
            Assert.Equal(definition.DefaultModel, model.Name);
            Assert.Equal(definition.ModelBrand, model.Brand);
        }
        Assert.IsType<VirtualUrControllerOptions>(VirtualControllerRegistry.DefaultOptions(RobotType.UR));
        Assert.Equal(RobotType.UR, VirtualControllerRegistry.Find("universal robots"));
        Assert.Null(VirtualControllerRegistry.Find("marlin"));
        Assert.Equal(30003, VirtualControllerRegistry.DriverPort(RobotType.UR));
    }

    [Fact]
    public void VirtualControllers_RefuseABrandWithoutOne_AndAnotherBrandsOptions()
    {
        ArgumentException none = Assert.Throws<ArgumentException>(() => VirtualControllerRegistry.DefaultOptions(RobotType.MARLIN));
        Assert.Equal("MARLIN devices have no virtual controller; ABB, UR, KUKA have one. (Parameter 'brand')", none.Message);
        Assert.False(VirtualControllerRegistry.Has(RobotType.HUMAN));
    }

    [Fact]
    public async Task VirtualControllers_RefuseAnotherBrandsOptions_WithoutStartingAnything()
    {
        ArgumentException wrong = await Assert.ThrowsAsync<ArgumentException>(
            () => VirtualControllerRegistry.StartAsync(RobotType.KUKA, new VirtualAbbControllerOptions(), Timeout()));
        Assert.Equal("A virtual KUKA controller takes VirtualKukaControllerOptions, not VirtualAbbControllerOptions. (Parameter 'options')", wrong.Message);
    }

    [Theory]
    [InlineData(RobotType.ABB, new[] { "driver", "monitor" }, "0 requests received, 0 executed, 0 malformed")]
    [InlineData(RobotType.UR, new[] { "script", "RTDE", "dashboard" }, "0 instructions received, 0 executed, 0 refused")]
    [InlineData(RobotType.KUKA, new[] { "driver", "monitor" }, "0 requests received, 0 executed, 0 refused")]
    public async Task VirtualControllers_StartOnLoopback_WithTheirPortsNamed(RobotType brand, string[] portNames, string summary)
    {
        VirtualControllerOptions settings = VirtualControllerRegistry.DefaultOptions(brand) with { InstantExecution = true };
        await using RunningVirtualController controller = await VirtualControllerRegistry.StartAsync(brand, settings, Timeout());

        Assert.Equal(brand, controller.Brand);
        Assert.Equal(portNames, controller.PortNames);
        Assert.Equal(portNames.Length, controller.Ports.Count);
        Assert.All(controller.Ports, p => Assert.InRange(p, 1, 65535));
        Assert.Equal(controller.Ports[0], controller.Port);
        Assert.Equal(summary, controller.Summary());
        Assert.Equal(BrandRegistry.For(brand).DefaultModel, controller.Model!.Name);
        Assert.Empty(controller.Errors);
        using var client = new System.Net.Sockets.TcpClient();
        await client.ConnectAsync(System.Net.IPAddress.Loopback, controller.Port, Timeout());
        Assert.True(client.Connected);
    }
}

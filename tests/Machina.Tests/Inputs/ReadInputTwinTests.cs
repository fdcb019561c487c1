using System.Collections.Concurrent;
using Machina.Simulation;
using Machina.Tests.Online;
using Machina.Tests.Support;

namespace Machina.Tests.Inputs;

/// <summary>
/// ReadDigital / ReadAnalog online on the twins that run the unchanged driver programs: a test sets the inputs, the value read
/// by the driver travels with the read's acknowledgement to <see cref="Robot.ReadDigitalAsync(string, bool, CancellationToken)"/>
/// and to <see cref="ActionExecutedArgs.ReadValue"/>.
/// </summary>
public class ReadInputTwinTests
{
    private static void RecordValues(Robot bot, ConcurrentDictionary<int, double?> values) =>
        bot.ActionExecuted += (_, e) => values[e.LastAction.Id] = e.ReadValue;

    [Fact]
    public async Task Abb_DInputAndAInput_ValuesArriveWithTheAcknowledgement()
    {
        await using var controller = new VirtualAbbController(new VirtualAbbControllerOptions
        {
            RunsRapid = true,
            InstantExecution = true,
            Model = RobotModels.Get("IRB 1600-8/1.45"),
        });
        await controller.StartAsync();
        controller.SetDigitalInput("DI_3", true);
        controller.SetAnalogInput("AI_2", 4.25);
        var values = new ConcurrentDictionary<int, double?>();
        Robot bot = await OnlineTestSupport.ConnectAsync(controller, b => RecordValues(b, values));
        try
        {
            Assert.True(await bot.ReadDigitalAsync("DI_3").WaitAsync(OnlineTestSupport.Limit));
            Assert.False(await bot.ReadDigitalAsync("DI_4").WaitAsync(OnlineTestSupport.Limit));
            Assert.Equal(4.25, await bot.ReadAnalogAsync("AI_2").WaitAsync(OnlineTestSupport.Limit), 5);

            controller.SetDigitalInput("DI_3", false);
            bot.Message("between");
            bot.ReadDigital("DI_3");
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(1.0, values[1]);
            Assert.Equal(0.0, values[2]);
            Assert.Equal(4.25, values[3]!.Value, 5);
            Assert.Null(values[4]);
            Assert.Equal(0.0, values[5]);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Ur_StandardAndToolInputs_ValuesArriveWithTheAcknowledgement()
    {
        await using VirtualUrController controller = await UrOnlineTestSupport.StartUrAsync(new VirtualUrControllerOptions());
        controller.SetDigitalInput(6, true);
        controller.SetDigitalInput(1, true, toolPin: true);
        controller.SetAnalogInput(1, 7.5);
        controller.SetAnalogInput(0, 0.012, toolPin: true);
        var values = new ConcurrentDictionary<int, double?>();
        Robot bot = await UrOnlineTestSupport.ConnectUrAsync(controller, b => RecordValues(b, values));
        try
        {
            Assert.True(await bot.ReadDigitalAsync(6).WaitAsync(OnlineTestSupport.Limit));
            Assert.False(await bot.ReadDigitalAsync(5).WaitAsync(OnlineTestSupport.Limit));
            Assert.True(await bot.ReadDigitalAsync(1, toolPin: true).WaitAsync(OnlineTestSupport.Limit));
            Assert.Equal(7.5, await bot.ReadAnalogAsync(1).WaitAsync(OnlineTestSupport.Limit), 6);
            Assert.Equal(0.012, await bot.ReadAnalogAsync(0, toolPin: true).WaitAsync(OnlineTestSupport.Limit), 6);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(1.0, values[1]);
            Assert.Equal(0.0, values[2]);
            Assert.Equal(7.5, values[4]!.Value, 6);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }

    [Fact]
    public async Task Kuka_InAndAnin_ValuesArriveWithTheAcknowledgement_OtherAcknowledgementsCarryNone()
    {
        await using VirtualKukaController controller = await KukaTestSupport.StartKukaAsync(new VirtualKukaControllerOptions());
        controller.SetDigitalInput(7, true);
        controller.SetAnalogInput(3, -0.25);
        var values = new ConcurrentDictionary<int, double?>();
        var (bot, _, _) = await KukaTestSupport.ConnectKukaAsync(controller, b => RecordValues(b, values));
        try
        {
            Assert.True(await bot.ReadDigitalAsync(7).WaitAsync(OnlineTestSupport.Limit));
            Assert.False(await bot.ReadDigitalAsync(8).WaitAsync(OnlineTestSupport.Limit));
            Assert.Equal(-0.25, await bot.ReadAnalogAsync(3).WaitAsync(OnlineTestSupport.Limit), 6);
            bot.WriteDigital(2, true);
            await bot.WaitForCompletionAsync().WaitAsync(OnlineTestSupport.Limit);

            Assert.Equal(1.0, values[1]);
            Assert.Equal(0.0, values[2]);
            Assert.Null(values[4]);
        }
        finally
        {
            await bot.DisconnectAsync();
        }
    }
}

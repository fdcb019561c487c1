namespace Machina.Tests.Cli;

/// <summary><c>machina drivers</c> says what each brand really needs once the files are written.</summary>
public sealed class DriversCommandTests
{
    [Fact]
    public async Task Drivers_Ur_SaysNothingIsLoadedAndThePortIs30003()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "ur", "--host", "192.168.125.1", "--port", "7000", "--out", "driver");

        Assert.Equal(0, result.Exit);
        Assert.Equal(
            "Wrote 1 UR driver file for reading, filled in with 192.168.125.1:7000 as the computer it connects back to. " +
            "Nothing to load on a UR: machina run sends this script to the robot's script port itself, with this computer's address " +
            "and a free port filled in. Give the robot a fixed address the computer can reach (and that can reach the computer), put " +
            "an e-Series robot in remote control, then: machina run PROGRAM --brand ur --host ROBOT_ADDRESS --port 30003",
            result.Stderr.TrimEnd());
        Assert.DoesNotContain("Load them", result.Stderr, StringComparison.Ordinal);
    }

    [Fact]
    public async Task Drivers_Abb_NamesTheTasksAndTheMonitorPort()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "abb", "--host", "192.168.125.1", "--port", "7000", "--out", "driver");

        Assert.Equal(0, result.Exit);
        Assert.Equal(
            "Wrote 4 ABB driver files for 192.168.125.1:7000. With RobotStudio or the FlexPendant, load machina_abb_driver.mod into the " +
            "motion task T_ROB1 and start it in manual reduced speed: it listens on 192.168.125.1:7000. For live positions, load " +
            "machina_abb_monitor.mod into a second task, T_MACHINA_MONITOR (Multitasking option 623-1); it uses port 7001. " +
            "Then: machina run PROGRAM --brand abb --host 192.168.125.1 --port 7000",
            result.Stderr.TrimEnd());
    }

    [Fact]
    public async Task Drivers_Kuka_NamesTheFoldersTheOptionAndTheMonitorPort()
    {
        using var cli = new CliRunner();

        CliResult result = await cli.RunAsync("drivers", "kuka", "--host", "172.31.1.147", "--port", "54600", "--out", "driver");

        Assert.Equal(0, result.Exit);
        Assert.Equal(
            "Wrote 6 KUKA driver files for 172.31.1.147:54600 (needs the KUKA.EthernetKRL option). Copy the .xml files to " +
            @"C:\KRC\ROBOTER\Config\User\Common\EthernetKRL and the .src and .dat files to R1\Program; for live positions add " +
            "machina_kuka_monitor( ) to the USER PLC fold of sps.sub (it uses port 54601; flags 1 to 3 and timer 16 must be free). " +
            "Select machina_kuka_driver and start it in T1: it listens on 172.31.1.147:54600. " +
            "Then: machina run PROGRAM --brand kuka --host 172.31.1.147 --port 54600",
            result.Stderr.TrimEnd());
        Assert.Equal(6, Directory.GetFiles(cli.PathOf("driver")).Length);
    }
}

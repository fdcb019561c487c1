using System.Net;

namespace Machina.Simulation.Rapid;

/// <summary>
/// The controller's own network addresses as programs name them: every IRC5 has its service port at the fixed address
/// 192.168.125.1, and programs written for a real controller bind their servers to it; the twin stands in for that controller, so
/// a bind to it is a bind to the address the twin serves on (<see cref="RapidTwinOptions.LanIp"/>).
/// </summary>
internal sealed partial class RapidTwinController
{
    /// <summary>The IRC5 service port's fixed address.</summary>
    internal static readonly IPAddress ServicePortAddress = IPAddress.Parse("192.168.125.1");

    /// <summary>Where a program's SocketBind to <paramref name="address"/> binds: the service port's address is the twin's own.</summary>
    internal IPAddress BindAddress(IPAddress address) => address.Equals(ServicePortAddress) ? IPAddress.Parse(Options.LanIp) : address;
}

using Machina.Simulation.Rapid;
using Machina.Simulation.Twin;

namespace Machina.Simulation.Rws;

/// <summary>The virtual ABB's web services: Robot Web Services 1.0 in front of its RAPID twin, with ABB's default user.</summary>
internal static class RwsWebServices
{
    private const string User = "Default User";
    private const string Password = "robotics";

    /// <summary>Starts Robot Web Services for <paramref name="twin"/> on a free loopback port.</summary>
    internal static TwinWebServices Serve(RapidTwinController twin)
    {
        var server = new RwsTwinServer(twin, User, Password);
        server.Start();
        return new TwinWebServices(server.Port, "Robot Web Services (RWS 1.0)", $"user \"{User}\", password \"{Password}\"",
            [$"RWS's /fileservice/$HOME is RAPID's HOME:, the folder {twin.HomeDirectory}."], server);
    }
}

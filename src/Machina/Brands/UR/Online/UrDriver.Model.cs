namespace Machina;

internal sealed partial class UrDriver
{
    /// <summary>
    /// Asks the dashboard server which arm this is (<c>get robot model</c>, and <c>PolyscopeVersion</c> to tell CB-Series from
    /// e-Series) for the handshake. Never fails the connection: a dashboard that cannot be
    /// reached within <paramref name="timeout"/> or does not know the command gives no name (logged).
    /// </summary>
    private async Task<(string? Name, RobotModel? Model)> ReadModelAsync(TimeSpan timeout, CancellationToken cancellationToken)
    {
        using var deadline = new CancellationTokenSource(timeout > TimeSpan.Zero ? timeout : TimeSpan.Zero, Time);
        using var both = CancellationTokenSource.CreateLinkedTokenSource(deadline.Token, cancellationToken);
        try
        {
            await using UrDashboard dashboard = await UrDashboard.OpenAsync(_host, _ports.Dashboard, both.Token).ConfigureAwait(false);
            string model = (await dashboard.CommandAsync("get robot model", both.Token).ConfigureAwait(false)).Trim();
            if (model.Length == 0 || model.StartsWith("could not understand", StringComparison.OrdinalIgnoreCase))
            {
                Log.Info($"The UR dashboard server did not name the arm (\"{model}\"); the robot keeps the model it has.");
                return (null, null);
            }
            string software = (await dashboard.CommandAsync("PolyscopeVersion", both.Token).ConfigureAwait(false)).Trim();
            bool known = !software.StartsWith("could not understand", StringComparison.OrdinalIgnoreCase) && software.Length > 0;
            string named = known ? $"{model} ({software})" : model;
            return (named, UrModelName.Find(model, known ? software : null));
        }
        catch (Exception ex) when (ex is RobotConnectionException || ex is OperationCanceledException && !cancellationToken.IsCancellationRequested)
        {
            Log.Info($"Could not ask the UR dashboard server at {_host}:{_ports.Dashboard} which arm this is ({ex.Message}); the robot keeps the model it has.");
            return (null, null);
        }
    }
}

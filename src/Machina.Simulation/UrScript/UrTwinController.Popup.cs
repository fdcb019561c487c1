using Machina.Simulation.Twin;

namespace Machina.Simulation.UrScript;

internal sealed partial class UrTwinController
{
    private readonly Lock _popupGate = new();
    private string? _popup;
    private ManualResetEventSlim? _popupClosed;

    /// <summary>The text of the popup a program shows (<c>popup</c>) until it is closed, or null.</summary>
    public string? Popup
    {
        get
        {
            lock (_popupGate)
            {
                return _popup;
            }
        }
    }

    /// <summary>
    /// Shows a program's popup (it replaces one still open, which counts as closed). With <paramref name="blocking"/> the program
    /// is suspended until it is closed (the Script Manual: "program will be suspended until 'continue' is pressed"; here the
    /// dashboard's <c>close popup</c>, <see cref="ClosePopup"/>) or the program is stopped (the popup closes with it).
    /// </summary>
    public void ShowPopup(string text, bool blocking, CancellationToken cancellation)
    {
        var closed = new ManualResetEventSlim(false);
        ManualResetEventSlim? replaced;
        lock (_popupGate)
        {
            replaced = _popupClosed;
            (_popup, _popupClosed) = (text, closed);
        }
        replaced?.Set();
        if (!blocking)
        {
            return;
        }
        TwinWait.Blocking();
        try
        {
            closed.Wait(cancellation);
        }
        finally
        {
            lock (_popupGate)
            {
                if (_popupClosed == closed)
                {
                    (_popup, _popupClosed) = (null, null);
                }
            }
        }
    }

    /// <summary>Closes the program's popup (a blocking one lets the program go on); false when none is open.</summary>
    public bool ClosePopup()
    {
        ManualResetEventSlim? closed;
        lock (_popupGate)
        {
            closed = _popupClosed;
            (_popup, _popupClosed) = (null, null);
        }
        closed?.Set();
        return closed is not null;
    }
}

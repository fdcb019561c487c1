namespace Machina.Simulation.Krl;

/// <summary>The TRIGGERs waiting for the next motion (see <see cref="KrlTrigger"/>).</summary>
internal sealed partial class KrlMachine
{
    private readonly List<(KrlTrigger Trigger, object[] Frame)> _triggers = [];

    /// <summary>Runs the waiting triggers of the motion's start (or end), in the order they were given, and forgets them.</summary>
    private void RunTriggers(bool atEnd)
    {
        if (_triggers.Count == 0)
        {
            return;
        }
        int line = Line;
        for (int i = 0; i < _triggers.Count; i++)
        {
            (KrlTrigger trigger, object[] frame) = _triggers[i];
            if (trigger.AtEnd == atEnd)
            {
                _triggers.RemoveAt(i--);
                Line = trigger.Line;
                Statement(trigger.Action, frame);
            }
        }
        Line = line;
    }
}

namespace Machina.Simulation;

public sealed partial class VirtualKukaController
{
    /// <summary>
    /// A restart dropped what the driver held: each held action is marked dropped and counted lost. The driver may still run
    /// one (with nobody connected, before it is reset): whoever settles it then (its acknowledgement, its progress after the
    /// restart) logs it executed (<see cref="VirtualController{TState}.RanOutsideBuffer"/>). After a program reset the dropped
    /// ones are forgotten (<see cref="ForgetDropped"/>): the reset emptied the ring before they ran.
    /// </summary>
    private protected override int DiscardHeld()
    {
        int dropped = 0;
        lock (Gate)
        {
            for (int i = 0; i < _held.Count; i++)
            {
                if (!_held[i].Dropped)
                {
                    _held[i] = _held[i] with { Dropped = true };
                    dropped++;
                }
            }
        }
        return dropped;
    }

    /// <summary>Forgets the actions a restart dropped: the driver, reset, will not run them (its ring starts empty).</summary>
    private void ForgetDropped()
    {
        lock (Gate)
        {
            _held.RemoveAll(a => a.Dropped);
        }
    }
}

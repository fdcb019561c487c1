namespace Machina.Simulation.Krl;

/// <summary>EKI_GetFrameArray (registered with the system routines, <see cref="KrlBuiltins"/>).</summary>
internal sealed partial class KrlTwinController
{
    /// <summary>
    /// EKI_GetFrameArray(channel, tag, frames[]): the next FRAME values of the tag's memory into the array from its first element,
    /// until the array is full or the memory empty (as EKI_GetRealArray); Read is how many were read, Buff how many remain.
    /// </summary>
    internal KrlStructValue EkiGetFrameArray(string name, string tag, KrlPlace place)
    {
        EkiChannel channel = Channel(name);
        if (!channel.Configuration.Receive.Any(e => e.Tag == tag && e.Type == "FRAME"))
        {
            throw new KrlRuntimeException($"EthernetKRL: EKI_GetFrameArray reads an element of Type=\"FRAME\"; the channel {name} receives no FRAME element {tag}");
        }
        var array = (KrlArrayValue)place.Get();
        object[] items = array.ToObjects();
        int read = 0, remaining = channel.Count(tag);
        while (read < items.Length && channel.Take(tag, out remaining) is { } value)
        {
            items[read++] = new KrlStructValue(KrlTypes.Frame, [.. EkiChannel.ParseFrame(value).Select(p => (object)p)]);
        }
        place.Set(new KrlArrayValue(array.Type, items));
        return new KrlStructValue(KrlTypes.EkiStatus,
            [KrlValues.Box(remaining), KrlValues.Box(read), KrlValues.Box(0), KrlValues.Box(channel.Connected), KrlValues.Box(0)]);
    }
}

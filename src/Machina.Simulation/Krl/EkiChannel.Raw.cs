namespace Machina.Simulation.Krl;

/// <summary>
/// Raw mode (<c>&lt;RECEIVE&gt;&lt;RAW&gt;</c>): each binary record received is one value of the RAW element's memory, which
/// EKI_GetString reads, and sets the element's flag (see <see cref="EkiRawSplitter"/>).
/// </summary>
internal sealed partial class EkiChannel
{
    /// <summary>A received record as a document of one value.</summary>
    private List<(string Tag, string Value)> RawDocument(string record) => [(Configuration.RawReceive!.Tag, record)];

    /// <summary>The flags a received record sets.</summary>
    private List<int> RawFlags() => Configuration.RawReceive!.SetFlag > 0 ? [Configuration.RawReceive.SetFlag] : [];
}

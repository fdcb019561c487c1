namespace Machina;

/// <summary>The kinds of messages the RAPID driver and monitor send to the host.</summary>
internal enum AbbMessageKind
{
    /// <summary><c>@id code;</c> (or <c>code;</c> for id 0): the request with that id has been executed.</summary>
    Acknowledgement,

    /// <summary><c>$code v1 … vn;</c>: state data (version, pose, joints, external axes, monitor update).</summary>
    Data,

    /// <summary><c>$@id 101 …;</c>: reply to a GET_INFO request, kept as text.</summary>
    Information,
}

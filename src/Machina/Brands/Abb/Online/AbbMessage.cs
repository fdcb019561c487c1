namespace Machina;

/// <summary>
/// One message received from the ABB driver or monitor, already split from the byte stream.
/// Acknowledgements carry no allocation; data messages carry their numbers; typed views check code and count.
/// </summary>
internal readonly struct AbbMessage
{
    private readonly double[]? _values;

    private AbbMessage(AbbMessageKind kind, int id, int code, double[]? values, string? text)
    {
        Kind = kind;
        Id = id;
        Code = code;
        _values = values;
        Text = text;
    }

    /// <summary>What kind of message this is.</summary>
    public AbbMessageKind Kind { get; }

    /// <summary>The action id (acknowledgement and information messages; 0 otherwise).</summary>
    public int Id { get; }

    /// <summary>The instruction code (acknowledgement) or response code (data).</summary>
    public int Code { get; }

    /// <summary>The numbers of a data message (empty otherwise).</summary>
    public ReadOnlySpan<double> Values => _values;

    /// <summary>The payload of an information message, or null.</summary>
    public string? Text { get; }

    /// <summary>An acknowledgement of request <paramref name="id"/>.</summary>
    public static AbbMessage Acknowledgement(int id, int code) => new(AbbMessageKind.Acknowledgement, id, code, null, null);

    /// <summary>A data message with its numbers.</summary>
    public static AbbMessage Data(int code, double[] values) => new(AbbMessageKind.Data, 0, code, values, null);

    /// <summary>A GET_INFO reply with its text payload.</summary>
    public static AbbMessage Information(int id, int code, string text) => new(AbbMessageKind.Information, id, code, null, text);

    /// <summary>The acknowledgement this message is.</summary>
    public AbbAcknowledgement ToAcknowledgement()
    {
        Expect(AbbMessageKind.Acknowledgement, null, 0);
        return new AbbAcknowledgement(Id, Code);
    }

    /// <summary>The driver version of a <c>$20</c> message.</summary>
    public AbbDriverVersion ToVersion()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.Version, 3);
        return new AbbDriverVersion(Integer(0), Integer(1), Integer(2));
    }

    /// <summary>The flange pose of a <c>$21</c> message.</summary>
    public AbbPose ToPose()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.Pose, 7);
        return new AbbPose(new Vector(_values![0], _values[1], _values[2]), Quaternion(3));
    }

    /// <summary>The joint angles (degrees) of a <c>$22</c> message.</summary>
    public Joints ToJoints()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.Joints, 6);
        return Joints.FromArray(_values);
    }

    /// <summary>The external axes of a <c>$23</c> message (values of 9E9 and above are unset axes).</summary>
    public ExternalAxes ToExternalAxes()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.ExternalAxes, 6);
        return Axes(0);
    }

    /// <summary>The driver's progress of a <c>$25</c> message: ids of the last request executed and the last one received.</summary>
    public DeviceProgress ToProgress()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.Progress, 2);
        return new DeviceProgress(Integer(0), Integer(1));
    }

    /// <summary>The failed request's id and the failure code of a <c>$26</c> message.</summary>
    public (int Id, int Code) ToFailure()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.Failure, 2);
        return (Whole(0), Whole(1));
    }

    /// <summary>The monitor report of a <c>$24</c> message.</summary>
    public AbbMonitorUpdate ToMonitorUpdate()
    {
        Expect(AbbMessageKind.Data, AbbResponseCode.FullPose, 19);
        return new AbbMonitorUpdate(
            new Vector(_values![0], _values[1], _values[2]), Quaternion(3), Joints.FromArray(_values.AsSpan(7, 6)), Axes(13));
    }

    /// <summary>Readable form, e.g. <c>@12 1;</c> or <c>$22 0 0 0 0 90 0;</c>.</summary>
    public override string ToString() => Kind switch
    {
        AbbMessageKind.Acknowledgement => Id == 0 ? $"{Code};" : $"@{Id} {Code};",
        AbbMessageKind.Information => $"$@{Id} {Code} {Text};",
        _ => $"${Code}" + string.Concat(_values!.Select(v => " " + Num.G(v))) + ";",
    };

    private void Expect(AbbMessageKind kind, AbbResponseCode? code, int count)
    {
        if (Kind != kind || (code is not null && Code != (int)code.Value))
        {
            throw new InvalidOperationException($"Expected a {kind} {code} message but this is {this}.");
        }
        if (kind == AbbMessageKind.Data && _values!.Length < count)
        {
            throw new AbbProtocolException($"The controller sent a ${Code} message with {_values.Length} values where {count} were expected.", ToString());
        }
    }

    private int Integer(int index)
    {
        double v = _values![index];
        if (v != Math.Floor(v) || v < 0 || v > int.MaxValue)
        {
            throw new AbbProtocolException("The controller sent a version that is not made of whole numbers.", ToString());
        }
        return (int)v;
    }

    private int Whole(int index)
    {
        double v = _values![index];
        if (v != Math.Floor(v) || v < 0 || v > int.MaxValue)
        {
            throw new AbbProtocolException($"The controller sent a ${Code} message whose value {Num.G(v)} is not a whole number.", ToString());
        }
        return (int)v;
    }

    private Rotation Quaternion(int start)
    {
        try
        {
            return Rotation.FromQuaternion(_values![start], _values[start + 1], _values[start + 2], _values[start + 3]);
        }
        catch (ArgumentException e)
        {
            throw new AbbProtocolException($"The controller sent an invalid quaternion: {e.Message}", ToString());
        }
    }

    private ExternalAxes Axes(int start)
    {
        var v = _values!;
        return new ExternalAxes(v[start], v[start + 1], v[start + 2], v[start + 3], v[start + 4], v[start + 5]);
    }
}

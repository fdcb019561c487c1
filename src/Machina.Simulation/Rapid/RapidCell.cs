namespace Machina.Simulation.Rapid;

/// <summary>
/// A storage place for data: a global, a persistent, or a local of a routine call. It counts its writes (<see cref="Version"/>): a
/// new value and every write into a part of the value in place (a component, an element, a record copied into the one it holds)
/// change the count, so that a reader can tell that the data are the same as when it last looked (a move's tooldata and wobjdata:
/// their frames are taken again without comparing ~40 components) and a reader on another thread (RWS) can take a whole value as
/// one state of it (<see cref="Read{T}"/>).
/// </summary>
internal sealed class RapidCell(string name, RapidDataType type, RapidStorage storage, object value)
{
    /// <summary>How many times <see cref="Read{T}"/> reads a value that is being written before it gives up.</summary>
    private const int ReadAttempts = 10_000;

    private object _value = value;

    /// <summary>Twice the writes, plus one while a write of several parts in place is under way (<see cref="BeginWrite"/>).</summary>
    private long _version;

    /// <summary>The data's name.</summary>
    public string Name { get; } = name;

    /// <summary>Its static type.</summary>
    public RapidDataType Type { get; } = type;

    /// <summary>CONST, VAR or PERS.</summary>
    public RapidStorage Storage { get; } = storage;

    /// <summary>The value now; setting it counts a write.</summary>
    public object Value
    {
        get => _value;
        set
        {
            _value = value;
            Written();
        }
    }

    /// <summary>
    /// The count of writes: equal at two reads (with the same <see cref="Value"/> object) when nothing was written in between, the
    /// value's parts included; odd while a write of several parts is under way.
    /// </summary>
    public long Version => Volatile.Read(ref _version);

    /// <summary>
    /// True once an IPers order watches this persistent datum (or a part of it): only its writes are counted and wake a motion, so
    /// that writes of other persistent data (our driver's <c>machinaMotionId := r.id</c> at every move) cost nothing more than a store.
    /// </summary>
    public bool Watched { get; set; }

    /// <summary>
    /// Counts a write of one part of the value in place (a component or element: one reference stored) or of the whole value. Only
    /// the data's task writes in place; the count is published after the part (a reader that sees the part sees the count change).
    /// </summary>
    public void Written() => Volatile.Write(ref _version, _version + 2);

    /// <summary>Starts a write of several parts in place (a record copied into the one the cell holds): the count is odd until <see cref="EndWrite"/>.</summary>
    public void BeginWrite() => Interlocked.Increment(ref _version); // a full fence: the parts are written after the odd count is seen

    /// <summary>Ends a write <see cref="BeginWrite"/> started.</summary>
    public void EndWrite() => Volatile.Write(ref _version, _version + 1);

    /// <summary>
    /// <paramref name="read"/> of the value as one state of it, for a reader on another thread than the data's task (RWS): read again
    /// while the task writes the value or a part of it meanwhile; null when it was written during each of many attempts.
    /// </summary>
    public T? Read<T>(Func<object, T> read)
        where T : class
    {
        var wait = new SpinWait();
        for (int attempt = 0; attempt < ReadAttempts; attempt++)
        {
            long before = Volatile.Read(ref _version);
            if ((before & 1) == 0)
            {
                T result = read(Volatile.Read(ref _value));
                Interlocked.MemoryBarrier(); // the parts read above are read before the count below
                if (Volatile.Read(ref _version) == before)
                {
                    return result;
                }
            }
            wait.SpinOnce();
        }
        return null;
    }
}

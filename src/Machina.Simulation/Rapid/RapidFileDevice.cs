namespace Machina.Simulation.Rapid;

/// <summary>An <c>iodev</c>: a file of the twin's sandbox that Open opened (for reading, writing, appending, or binary both), until Close.</summary>
internal sealed class RapidFileDevice
{
    /// <summary>The open file, or null when closed.</summary>
    public FileStream? Stream { get; private set; }

    /// <summary>The reader of a file opened for reading (\Read, \Bin).</summary>
    public StreamReader? Reader { get; private set; }

    /// <summary>The writer of a file opened for writing (\Write, \Append, \Bin); every Write reaches the file at once.</summary>
    public StreamWriter? Writer { get; private set; }

    /// <summary>Opens <paramref name="path"/> with <paramref name="mode"/> for <paramref name="access"/>.</summary>
    public void Open(string path, FileMode mode, FileAccess access)
    {
        Stream = new FileStream(path, mode, access, FileShare.ReadWrite);
        Reader = access.HasFlag(FileAccess.Read) ? new StreamReader(Stream, leaveOpen: true) : null;
        Writer = access.HasFlag(FileAccess.Write) ? new StreamWriter(Stream, leaveOpen: true) { AutoFlush = true, NewLine = "\n" } : null;
    }

    /// <summary>Rewind: reads and writes start again at the beginning of the file.</summary>
    public void Rewind()
    {
        if (Stream is null)
        {
            return;
        }
        Stream.Seek(0, SeekOrigin.Begin);
        Reader?.DiscardBufferedData();
    }

    /// <summary>Close: the file is flushed and released.</summary>
    public void Close()
    {
        Writer?.Dispose();
        Reader?.Dispose();
        Stream?.Dispose();
        (Writer, Reader, Stream) = (null, null, null);
    }
}

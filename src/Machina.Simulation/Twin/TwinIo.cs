namespace Machina.Simulation.Twin;

/// <summary>The controller's inputs, outputs and fieldbus registers (a controller has a fixed number of each).</summary>
internal sealed class TwinIo
{
    private readonly Lock _gate = new();
    private readonly Dictionary<string, bool[]> _bits = new(StringComparer.Ordinal);
    private readonly Dictionary<string, double[]> _numbers = new(StringComparer.Ordinal);

    /// <summary>Declares a bank of digital signals (all false).</summary>
    public void AddBits(string bank, int count) => _bits[bank] = new bool[count];

    /// <summary>Declares a bank of numeric signals or registers (all 0).</summary>
    public void AddNumbers(string bank, int count) => _numbers[bank] = new double[count];

    /// <summary>How many signals a bank has (0 when there is no such bank).</summary>
    public int Count(string bank) => _bits.TryGetValue(bank, out bool[]? b) ? b.Length : _numbers.TryGetValue(bank, out double[]? n) ? n.Length : 0;

    /// <summary>Reads a digital signal.</summary>
    public bool GetBit(string bank, int index)
    {
        lock (_gate)
        {
            return _bits[bank][index];
        }
    }

    /// <summary>Writes a digital signal.</summary>
    public void SetBit(string bank, int index, bool value)
    {
        lock (_gate)
        {
            _bits[bank][index] = value;
        }
    }

    /// <summary>Reads a numeric signal or register.</summary>
    public double GetNumber(string bank, int index)
    {
        lock (_gate)
        {
            return _numbers[bank][index];
        }
    }

    /// <summary>Writes a numeric signal or register.</summary>
    public void SetNumber(string bank, int index, double value)
    {
        lock (_gate)
        {
            _numbers[bank][index] = value;
        }
    }
}

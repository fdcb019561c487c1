namespace Machina.Simulation.Krl;

/// <summary>
/// An RSI context switched on, from RSI_ON (ST_ON) to RSI_OFF: the ETHERNET object's socket, the IPOC, the cycles' schedule, the
/// values the sensor sent last and the late answers. As on the controller, the exchange runs every cycle from RSI_ON on: between
/// sensor-guided motions a thread of its own exchanges the datagrams (<see cref="Start"/>), and RSI_MOVECORR takes the exchange over
/// (<see cref="Take"/>) for the cycles that move the arm, then gives it back.
/// </summary>
internal sealed class RsiSession(RsiContext context, RsiObject ethernet, RsiEthernetConfiguration configuration, bool relative, double cycle) : IDisposable
{
    private readonly SemaphoreSlim _turn = new(1, 1);
    private readonly CancellationTokenSource _stop = new();
    private Task? _idle;
    private string? _fault;

    /// <summary>The context that is on.</summary>
    public RsiContext Context { get; } = context;

    /// <summary>The context's ETHERNET object.</summary>
    public RsiObject Ethernet { get; } = ethernet;

    /// <summary>The socket and the documents of the ETHERNET object's configuration.</summary>
    public RsiExchange Exchange { get; } = new(configuration, (int)ethernet.Number("Precision", 4));

    /// <summary>#RELATIVE corrections (added up) rather than #ABSOLUTE ones (from where the motion started).</summary>
    public bool Relative { get; } = relative;

    /// <summary>The cycle in seconds: 0.004 (#IPO_FAST) or 0.012 (#IPO).</summary>
    public double Cycle { get; } = cycle;

    /// <summary>The ETHERNET object's received values by output index (1 to 64), kept from cycle to cycle (HOLDON).</summary>
    public double[] Outputs { get; } = new double[65];

    /// <summary>The ETHERNET object's inputs by index (1 to 64), sent in the robot's document.</summary>
    public double[] Inputs { get; } = new double[65];

    /// <summary>
    /// The program's command without corrections (ASPos, RSol): where the arm stood at RSI_ON, then where the last RSI_MOVECORR
    /// started (its corrections stay applied after it, as long as RSI is on).
    /// </summary>
    public (Joints Axes, Pose Tcp) Commanded { get; set; }

    /// <summary>The IPOC of the last cycle (ms).</summary>
    public long Ipoc { get; set; }

    /// <summary>The end of the cycle to come, a timestamp of the controller's time source (the next one starts there).</summary>
    public long Deadline { get; set; }

    /// <summary>Cycles run since RSI_ON.</summary>
    public int Cycles { get; set; }

    /// <summary>Late or missing answers since RSI_ON (DEF_Delay).</summary>
    public int Delay { get; set; }

    /// <summary>Late or missing answers in a row now.</summary>
    public int LateInRow { get; set; }

    /// <summary>The error that ended the exchange between motions (RSITimeout), given to the program at its next RSI statement.</summary>
    public string? Fault => Volatile.Read(ref _fault);

    /// <summary>Starts the exchange between motions: <paramref name="cycleBetweenMotions"/> runs one cycle; an error ends it as <see cref="Fault"/>.</summary>
    public void Start(TwinClockWait waitUntil, Action<CancellationToken> cycleBetweenMotions)
    {
        CancellationToken stop = _stop.Token;
        _idle = Task.Factory.StartNew(() =>
        {
            try
            {
                while (!stop.IsCancellationRequested)
                {
                    waitUntil(stop); // the cycle's start: RSI_MOVECORR, right after RSI_ON, takes the first cycle
                    _turn.Wait(stop);
                    try
                    {
                        cycleBetweenMotions(stop);
                    }
                    finally
                    {
                        _turn.Release();
                    }
                }
            }
            catch (OperationCanceledException)
            {
                // RSI_OFF
            }
            catch (KrlRuntimeException ex)
            {
                Volatile.Write(ref _fault, ex.Message);
            }
        }, stop, TaskCreationOptions.LongRunning, TaskScheduler.Default);
    }

    /// <summary>Takes the exchange over from the thread between motions (waiting for its cycle to end); dispose the result to give it back.</summary>
    public IDisposable Take(CancellationToken cancellation)
    {
        _turn.Wait(cancellation);
        return new Turn(_turn);
    }

    /// <summary>Ends the exchange (RSI_OFF, the program's end): the thread between motions stops and the socket closes.</summary>
    public void Dispose()
    {
        _stop.Cancel();
        try
        {
            _idle?.Wait(TimeSpan.FromSeconds(5));
        }
        catch (AggregateException)
        {
            // The thread's own errors are in Fault.
        }
        Exchange.Dispose();
        _stop.Dispose();
        _turn.Dispose();
    }

    private sealed class Turn(SemaphoreSlim turn) : IDisposable
    {
        private int _released;

        public void Dispose()
        {
            if (Interlocked.Exchange(ref _released, 1) == 0)
            {
                turn.Release();
            }
        }
    }
}

/// <summary>Waits until the next RSI cycle starts (or the exchange stops).</summary>
internal delegate void TwinClockWait(CancellationToken cancellation);

using System.Diagnostics;

namespace Machina.Benchmarks;

/// <summary>
/// With <c>jitlog=1</c>, the child samples every 20 ms how many methods the JIT has compiled and how long it spent, to see
/// when a cold process stops compiling new code (the tiered JIT waits for that before it optimises the hot loops).
/// </summary>
internal sealed class JitSampler : IDisposable
{
    private readonly List<string> _samples = [];
    private readonly CancellationTokenSource _stop = new();
    private readonly Thread _thread;
    private readonly long _start = Stopwatch.GetTimestamp();

    public JitSampler()
    {
        _thread = new Thread(Sample) { IsBackground = true, Name = "jit sampler" };
        _thread.Start();
    }

    /// <summary>"ms:methods:jit ms" for each sample taken so far.</summary>
    public List<string> Samples()
    {
        lock (_samples)
        {
            return [.. _samples];
        }
    }

    private void Sample()
    {
        while (!_stop.Token.WaitHandle.WaitOne(20))
        {
            string line = $"{Stopwatch.GetElapsedTime(_start).TotalMilliseconds:0}:{System.Runtime.JitInfo.GetCompiledMethodCount()}:{System.Runtime.JitInfo.GetCompilationTime().TotalMilliseconds:0}";
            lock (_samples)
            {
                _samples.Add(line);
            }
        }
    }

    public void Dispose()
    {
        _stop.Cancel();
        _thread.Join();
        _stop.Dispose();
    }
}

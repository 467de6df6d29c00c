using System;
using System.Diagnostics;
using System.Threading;

namespace AcDream.Core.Physics.Timing;

/// <summary>
/// Runs one piece of work on two threads at once, the caller's and one kept waiting, without allocating:
/// <see cref="Run"/> wakes the second thread with <c>body(1)</c>, runs <c>body(0)</c>, and waits for it.
/// Records how long each thread's part took (<see cref="Busy"/>).
/// </summary>
internal sealed class TwoThreads : IDisposable
{
    private readonly ManualResetEventSlim _go = new(false), _done = new(false);
    private readonly Thread _thread;
    private Action<int>? _body;
    private volatile bool _stop;
    private double _busy1;

    public TwoThreads()
    {
        _thread = new Thread(Loop) { IsBackground = true, Name = "second thread" };
        _thread.Start();
    }

    /// <summary>The last run's time of the caller's part (0) and the second thread's (1), milliseconds.</summary>
    public (double Caller, double Second) Busy { get; private set; }

    /// <summary>Runs body(0) here and body(1) on the second thread, and returns when both are done.</summary>
    public void Run(Action<int> body)
    {
        _body = body;
        _go.Set();
        long t = Stopwatch.GetTimestamp();
        body(0);
        double caller = Stopwatch.GetElapsedTime(t).TotalMilliseconds;
        _done.Wait();
        _done.Reset();
        Busy = (caller, _busy1);
    }

    private void Loop()
    {
        while (true)
        {
            _go.Wait();
            _go.Reset();
            if (_stop)
                return;
            long t = Stopwatch.GetTimestamp();
            _body!(1);
            _busy1 = Stopwatch.GetElapsedTime(t).TotalMilliseconds;
            _done.Set();
        }
    }

    /// <summary>Ends the second thread.</summary>
    public void Dispose()
    {
        _stop = true;
        _go.Set();
        _thread.Join();
        _go.Dispose();
        _done.Dispose();
    }
}

using System.Threading;

namespace AcDream.Core.Physics.Tests.Support;

/// <summary>
/// Measures the managed bytes a piece of work allocates, deterministically while other tests run in
/// parallel: the work runs on a thread of its own (nothing else can be scheduled on it between the two
/// readings of <see cref="GC.GetAllocatedBytesForCurrentThread"/>), after a warm-up, in several rounds.
/// </summary>
internal static class Allocations
{
    /// <summary>
    /// Runs <paramref name="warmUp"/> once, then <paramref name="round"/> up to <paramref name="rounds"/>
    /// times, and returns the fewest bytes one round allocated (0 stops early). An allocation made on
    /// every call, or every few calls, shows in every round; a one-off cost of the runtime (a method
    /// compiled again at its optimized tier while the machine is busy) shows in one round only.
    /// </summary>
    public static long PerRound(Action warmUp, Action round, int rounds = 3)
    {
        long fewest = long.MaxValue;
        Exception? failure = null;
        var thread = new Thread(() =>
        {
            try
            {
                warmUp();
                for (int i = 0; i < rounds && fewest > 0; i++)
                {
                    long before = GC.GetAllocatedBytesForCurrentThread();
                    round();
                    fewest = Math.Min(fewest, GC.GetAllocatedBytesForCurrentThread() - before);
                    if (fewest > 0)
                        Thread.Sleep(50); // give the runtime's background compiler time to finish
                }
            }
            catch (Exception ex)
            {
                failure = ex;
            }
        }, maxStackSize: 16 << 20) { IsBackground = true, Name = "allocation measure" };
        thread.Start();
        thread.Join();
        if (failure is not null)
            throw new InvalidOperationException("the measured work threw", failure);
        return fewest;
    }
}

using AcDream.Core.Physics.Motion;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>The queue of motions waiting for their animations (the interpreter's and the motion table manager's).</summary>
public class PendingQueueTests
{
    [Fact]
    public void Entries_LeaveInTheOrderTheyCame_AcrossGrowth()
    {
        var q = new PendingQueue<(uint Motion, uint Count)>();
        for (uint i = 0; i < 20; i++)
            q.Add((0x41000000u + i, i));
        Assert.Equal(20, q.Count);
        q.RemoveFirst();
        q.RemoveFirst();
        Assert.Equal(18, q.Count);
        Assert.Equal((0x41000002u, 2u), q[0]);
        Assert.Equal((0x41000013u, 19u), q[17]);
    }

    [Fact]
    public void AnEntry_IsEditedInPlace()
    {
        var q = new PendingQueue<(uint Motion, uint Count)>();
        q.Add((1u, 3u));
        q[0].Count = 0; // truncate_animation_list zeroes an entry's animation count where it stands
        Assert.Equal((1u, 0u), q[0]);
    }

    [Fact]
    public void RemovingFromAnEmptyQueue_DoesNothing()
    {
        var q = new PendingQueue<(uint Motion, uint Count)>();
        q.RemoveFirst();
        Assert.Equal(0, q.Count);
    }

    [Fact]
    public void Restore_ReplacesTheWholeQueue()
    {
        var q = new PendingQueue<(uint Motion, uint Count)>();
        for (uint i = 0; i < 12; i++)
            q.Add((i, i));
        q.Restore([(7u, 1u), (8u, 0u)]);
        Assert.Equal(2, q.Count);
        Assert.Equal((7u, 1u), q[0]);
        Assert.Equal((8u, 0u), q[1]);
        q.RemoveFirst();
        Assert.Equal((8u, 0u), q[0]);
    }
}

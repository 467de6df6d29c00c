using AcDream.Core.Physics.Transitions;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.Transitions;

/// <summary>
/// The index of a crowded cell (not retail; it changes no result): for any region it must name exactly the
/// objects whose reach box meets the region, in the cell's order, as reading every object of the cell does.
/// </summary>
public class CellObjectIndexTests
{
    /// <summary>
    /// 400 objects of a 24 m cell (most a metre or two across, some exactly 6 m, some wider, some beyond the
    /// cell's edges) and 20,000 seeded regions from a point to 10 m across: each region's list is the one a plain
    /// box test of every object gives. Went red with the south-edge margin left out of the search (regions missed
    /// objects that start south of them and reach into them).
    /// </summary>
    [Fact]
    public void EveryRegion_Lists_TheObjectsAFullReadFinds_InTheCellsOrder()
    {
        var rng = new Random(3317);
        var slots = new ShadowObjectRegistry.Slot[400];
        for (int i = 0; i < slots.Length; i++)
        {
            var record = new ShadowObjectRegistry.Record { Id = (uint)i, Shapes = [], Rows = [] };
            float size = (i % 9) switch { 0 => 6f, 1 => 6f + 20f * rng.NextSingle(), _ => 0.2f + 2f * rng.NextSingle() };
            float sizeY = i % 11 == 0 ? 6.5f : size;
            var min = new Vector3(-8 + 36 * rng.NextSingle(), -8 + 36 * rng.NextSingle(), -1 + 3 * rng.NextSingle());
            slots[i] = new ShadowObjectRegistry.Slot(record, 0, min, min + new Vector3(size, sizeY, 2f));
        }
        var index = new CellObjectIndex();
        index.Build(0xA9B40001u, 1, slots);
        var found = new int[slots.Length];
        var expected = new List<int>();
        int hits = 0;
        for (int r = 0; r < 20_000; r++)
        {
            var min = new Vector3(-10 + 40 * rng.NextSingle(), -10 + 40 * rng.NextSingle(), -2 + 4 * rng.NextSingle());
            var max = min + new Vector3(10 * rng.NextSingle(), 10 * rng.NextSingle(), 3 * rng.NextSingle());
            expected.Clear();
            for (int i = 0; i < slots.Length; i++)
            {
                var (lo, hi) = (slots[i].ReachMin, slots[i].ReachMax);
                if (lo.X <= max.X && hi.X >= min.X && lo.Y <= max.Y && hi.Y >= min.Y && lo.Z <= max.Z && hi.Z >= min.Z)
                    expected.Add(i);
            }
            int n = index.Meeting(min, max, slots, found);
            Assert.True(expected.SequenceEqual(found[..n]), $"region {r} ({min} to {max}): listed [{string.Join(", ", found[..n])}], a full read finds [{string.Join(", ", expected)}]");
            hits += n;
        }
        Assert.True(hits > 20_000, $"the regions met only {hits} objects in all: the test says little");
    }
}

using AcDream.Core.Physics.Motion;
using AcDream.Core.Physics.Scenes;

namespace AcDream.Core.Physics.Tests.Motion;

/// <summary>A motion table is checked on construction and by its reader; every error names its field.</summary>
public class MotionTableTests
{
    private const uint Style = MotionCommand.NonCombat;
    private static readonly uint ReadyKey = MotionTable.CycleKey(Style, MotionCommand.Ready);

    private static MotionTable Build(Dictionary<uint, MotionData> cycles, IEnumerable<Animation>? animations = null,
        Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>? links = null) =>
        new(0x09000001, Style, new Dictionary<uint, uint> { [Style] = MotionCommand.Ready }, cycles, new Dictionary<uint, MotionData>(),
            links ?? new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>(), animations ?? [new Animation(0x03000001, 4, [])]);

    private static MotionData Cycle(uint anim = 0x03000001, float framerate = 30f, Vector3 velocity = default) =>
        new(0, velocity == default ? MotionDataFlags.None : MotionDataFlags.HasVelocity, [new AnimData(anim, 0, -1, framerate)], velocity, Vector3.Zero);

    [Fact]
    public void TheHumanoid_IsValid_AndKeysItsCyclesByStyleAndMotion()
    {
        var table = MotionTables.Humanoid();
        Assert.Equal(0x003D0003u, ReadyKey);
        Assert.True(table.Cycles.ContainsKey(0x003D0007));
        Assert.Equal(new Vector3(0, 4, 0), table.Cycles[0x003D0007].Velocity);
        Assert.Equal(8, table.Animations[0x03000F02].FrameCount);
    }

    // Links: two keys of `perKey` targets each, every one the same one-animation motion.
    private static Dictionary<uint, IReadOnlyDictionary<uint, MotionData>> ManyLinks(int perKey)
    {
        var data = Cycle();
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>();
        for (uint key = 0; key < 2; key++)
        {
            var inner = new Dictionary<uint, MotionData>(perKey);
            for (uint m = 0; m < perKey; m++)
                inner[0x45000000u + m] = data;
            links[ReadyKey + key] = inner;
        }
        return links;
    }

    [Fact]
    public void TheConstructor_CountsEveryLinkTowardsTheEntryCap_AsTheReaderDoes()
    {
        // 150 000 link entries under two keys: the reader refuses more than MaxEntries; so must the constructor.
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle() }, links: ManyLinks(75_000)));
        Assert.StartsWith($"entries: a table holds at most {MotionTable.MaxEntries} entries", ex.Message);
        // Exactly the cap (one animation, one cycle, the rest links) is a table.
        int links = MotionTable.MaxEntries - 2;
        var table = Build(new() { [ReadyKey] = Cycle() }, links: ManyLinks(links / 2));
        Assert.Equal(links, table.LinkKeys.Sum(k => table.LinksFrom(k)!.Count));
        // One more, as an animation, is refused.
        ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle() },
            [new Animation(0x03000001, 4, []), new Animation(0x03000002, 4, [])], ManyLinks(links / 2)));
        Assert.StartsWith("entries:", ex.Message);
    }

    [Fact]
    public void TheConstructor_RefusesOneEntryPastTheCap_WithNoAnimations()
    {
        // No animations: one cycle and MaxEntries link targets are MaxEntries + 1 entries, refused by the count after
        // the animations (the one inside the animation loop never runs).
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle() }, [], ManyLinks(MotionTable.MaxEntries / 2)));
        Assert.StartsWith($"entries: a table holds at most {MotionTable.MaxEntries} entries", ex.Message);
        Assert.Contains($"got {MotionTable.MaxEntries + 1}", ex.Message);
    }

    [Fact]
    public void TheReader_RefusesOneEntryPastTheCap_CountingLinksAsTheConstructorDoes()
    {
        // One animation, one cycle and MaxEntries - 1 links: one past the cap, all in one link key (the old reader
        // counted the key, not its targets).
        var json = new System.Text.StringBuilder("""
            { "id": "0x09000001", "defaultStyle": "0x8000003D", "styleDefaults": { "0x8000003D": "0x41000003" },
              "animations": { "0x03000001": { "numFrames": 4 } },
              "cycles": { "0x003D0003": { "anims": [{ "animId": "0x03000001", "framerate": 30 }] } }, "modifiers": {},
              "links": { "0x003D0003": {
            """);
        for (int m = 0; m < MotionTable.MaxEntries - 1; m++)
            json.Append(m == 0 ? "" : ",").Append("\"0x").Append((0x45000000 + m).ToString("X8")).Append("\": {\"anims\": []}");
        json.Append("} } }");
        var ex = Assert.Throws<SceneFormatException>(() => MotionTableReader.Parse(json.ToString()));
        Assert.StartsWith($"links.0x003D0003.0x{0x45000000 + MotionTable.MaxEntries - 2:X8}: a motion table holds at most {MotionTable.MaxEntries} entries", ex.Message);
    }

    [Fact]
    public void TheConstructor_RefusesUnknownMotionFlags_AsTheReaderDoes()
    {
        // The reader takes flags 0 to 3 only; the constructor took any byte.
        var odd = new MotionData(0, (MotionDataFlags)4, [new AnimData(0x03000001, 0, -1, 30f)], Vector3.Zero, Vector3.Zero);
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = odd }));
        Assert.StartsWith("cycles[0x003D0003].flags: must be 0 to 3", ex.Message);
    }

    [Fact]
    public void AMissingDefaultCycle_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Build(new Dictionary<uint, MotionData>()));
        Assert.StartsWith("styleDefaults[0x8000003D]: no cycle 0x003D0003", ex.Message);
    }

    [Fact]
    public void ADanglingAnimation_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle(anim: 0x03000099) }));
        Assert.StartsWith("cycles[0x003D0003].anims[0].animId: animation 0x03000099", ex.Message);
    }

    [Fact]
    public void ADanglingLinkAnimation_IsRefused()
    {
        var links = new Dictionary<uint, IReadOnlyDictionary<uint, MotionData>>
        {
            [ReadyKey] = new Dictionary<uint, MotionData> { [MotionCommand.WalkForward] = Cycle(anim: 0x03000077) },
        };
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle() }, links: links));
        Assert.StartsWith("links[0x003D0003][0x45000005].anims[0].animId", ex.Message);
    }

    [Fact]
    public void AZeroFrameAnimation_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle() }, [new Animation(0x03000001, 0, [])]));
        Assert.StartsWith("animations[0x03000001].numFrames", ex.Message);
    }

    [Theory]
    [InlineData(0f)]
    [InlineData(float.NaN)]
    [InlineData(float.PositiveInfinity)]
    public void AZeroOrNonFiniteFramerate_IsRefused(float framerate)
    {
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle(framerate: framerate) }));
        Assert.StartsWith("cycles[0x003D0003].anims[0].framerate", ex.Message);
    }

    [Fact]
    public void ANaNVelocity_IsRefused()
    {
        var ex = Assert.Throws<ArgumentException>(() => Build(new() { [ReadyKey] = Cycle(velocity: new Vector3(float.NaN, 0, 0)) }));
        Assert.StartsWith("cycles[0x003D0003].velocity", ex.Message);
    }

    [Fact]
    public void TheReader_ReadsTheTableShape_AndNamesTheJsonPathOfAnError()
    {
        const string text = """
            { "format": "ace-motion-table", "version": 1, "id": "0x09000001", "defaultStyle": "0x8000003D",
              "styleDefaults": { "0x8000003D": "0x41000003" },
              "cycles": { "0x003D0003": { "bitfield": 0, "flags": 0, "anims": [{ "animId": "0x03000001", "lowFrame": 0, "highFrame": -1, "framerate": 30 }], "velocity": [0, 0, 0], "omega": [0, 0, 0] } },
              "modifiers": {}, "links": {},
              "animations": { "0x03000001": { "flags": 0, "numParts": 1, "numFrames": 4, "posFrames": [] } } }
            """;
        var table = MotionTableReader.Parse(text);
        Assert.Equal(0x09000001u, table.Id);
        Assert.Equal(4, table.Animations[0x03000001].FrameCount);

        var bad = Assert.Throws<SceneFormatException>(() => MotionTableReader.Parse(text.Replace("\"framerate\": 30", "\"framerate\": \"fast\"")));
        Assert.Equal("cycles.0x003D0003.anims[0].framerate", bad.JsonPath);
        var zero = Assert.Throws<SceneFormatException>(() => MotionTableReader.Parse(text.Replace("\"framerate\": 30", "\"framerate\": 0")));
        Assert.Contains("cycles[0x003D0003].anims[0].framerate", zero.Message);
    }
}

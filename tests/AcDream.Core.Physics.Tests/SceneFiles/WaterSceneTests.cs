using System.Text.Json.Nodes;
using AcDream.Core.Physics.Scenes;
using AcDream.Core.Physics.World;

namespace AcDream.Core.Physics.Tests.SceneFiles;

/// <summary>
/// The built-in scene <c>water-walk</c> (docs/water.md): players running from dry land into the lake of
/// landblock 0xA9B4 and out of it, against depths and flags derived by hand from the decompile's rules.
/// </summary>
public class WaterSceneTests
{
    // The lake's bands along X (landblock 0xA9B4, flat at 0): dry up to 144; cells of column 6 (144..168) partly
    // water, their west corners dry: 0.1 west of the centre line 156 (calc_water_depth, acclient.c:353645) and 0.45
    // east of it; column 7 (168..192) entirely water, 0.9 (CObjCell::get_water_depth, acclient.c:347232).
    private static float Depth(float x) => x < 144 ? 0f : x <= 156 ? 0.1f : x <= 168 ? 0.45f : 0.9f;

    // The humanoid's lower sphere (centre 0.475 above the origin, radius 0.48) reaches 0.005 below the origin: a
    // grounded humanoid's origin stands 0.005 above the surface its sphere rests on.
    private static float RestZ(float x) => 0.005f - Depth(x);

    // A frame whose low point lies within 1 mm of a band's edge is not judged (the cell holding it is a tie).
    private static bool NearAnEdge(float x) => new[] { 144f, 156f, 168f, 192f }.Any(e => MathF.Abs(x - e) < 0.001f);

    /// <summary>Each frame's state (position, contact, the water flag) of one mover, as the scene runner steps it.</summary>
    private static List<MoverState> States(Scene scene, string name)
    {
        int m = scene.Movers.ToList().FindIndex(x => x.Name == name);
        var mover = scene.Movers[m];
        var engine = new PhysicsEngine(scene.World);
        var state = mover.Start;
        var body = mover.StartBody;
        var motion = mover.Commands!.Start(mover.Description, state, ref body, SceneRunner.Earlier(scene, []));
        var states = new List<MoverState>();
        for (int f = 0; f < mover.FrameCount; f++)
        {
            SceneRunner.Advance(engine, mover.Description, mover.Steps[f], state.Position, ref state, ref body, motion, f);
            states.Add(state);
        }
        return states;
    }

    /// <summary>
    /// <see cref="States"/> from the first frame that moved: a 60 Hz mover's first frame is shorter than the body's
    /// 1/30 s quantum and keeps the start state (the scene's floorZ start, origin on the terrain).
    /// </summary>
    private static List<MoverState> Moved(Scene scene, string name)
    {
        var start = scene.Movers.First(x => x.Name == name).Start.Position.Origin;
        return States(scene, name).SkipWhile(s => s.Position.Origin == start).ToList();
    }

    [Theory]
    [InlineData("east-into-the-lake")]
    [InlineData("north-east-60hz")]
    [InlineData("west-out-of-the-lake")]
    public void AGroundedPlayer_RestsTheBandsDepthBelowTheTerrain_OnAWaterPlaneWhereTheCellHasWater(string name)
    {
        // validate_walkable (acclient.c:314222) adds the depth: a sphere in contact rests that far down, and the
        // contact plane is water when the cell is not NOT_WATER (find_env_collisions, acclient.c:355043).
        var states = Moved(SceneLibrary.Load("water-walk"), name);
        int judged = 0;
        foreach (var s in states)
        {
            float x = s.Position.Origin.X;
            if (!s.Contact || NearAnEdge(x))
                continue;
            judged++;
            Assert.Equal(RestZ(x), s.Position.Origin.Z, 1e-4f);
            Assert.Equal(x > 144, s.ContactPlaneIsWater);
        }
        Assert.True(judged > 100, $"{name}: only {judged} grounded frames");
    }

    [Theory]
    [InlineData("east-into-the-lake")]
    [InlineData("north-east-60hz")]
    public void RunningIntoDeeperWater_ThePlayerDropsToEachDepth_NeverBelowIt(string name)
    {
        // The humanoid steps down 0.04 m, less than every change of depth: it leaves the ground at each band and
        // falls to the band's depth, landing on a water plane. No frame sinks below the depth under it.
        var states = Moved(SceneLibrary.Load("water-walk"), name);
        foreach (var s in states)
            Assert.True(s.Position.Origin.Z >= RestZ(s.Position.Origin.X) - 1e-4f, $"{name}: z {s.Position.Origin.Z} at x {s.Position.Origin.X}");
        foreach (float depth in new[] { 0.1f, 0.45f, 0.9f })
            Assert.Contains(states, s => s.Contact && MathF.Abs(s.Position.Origin.Z - (0.005f - depth)) < 1e-4f);
        Assert.Contains(states, s => !s.Contact);
    }

    [Fact]
    public void AnAllWaterLandblock_StopsThePlayerAtItsEdge()
    {
        // Landblock 0xAAB4 is entirely water: find_env_collisions answers COLLIDED for a player whose low point
        // is over it (acclient.c:355030). The runner arrives at x = 192 before the end and is held short of it.
        var states = States(SceneLibrary.Load("water-walk"), "east-into-the-lake");
        var last = states[^1];
        Assert.Equal(0xA9B4u, last.Position.CellId >> 16);
        Assert.InRange(last.Position.Origin.X, 191f, 192f);
        Assert.True(last.Contact && last.ContactPlaneIsWater);
        Assert.Equal(0.005f - 0.9f, last.Position.Origin.Z, 1e-4f);
        Assert.True(states.Count(s => s.Position.Origin.X > 191f) > 10, "the runner was not held at the edge");
    }

    [Fact]
    public void RunningOutOfTheLake_EachShallowerBandLiftsThePlayerAtOnce()
    {
        // Out of the water the sphere lies deeper than the new band's depth: validate_walkable pushes it up in the
        // same frame (its Adjusted arm), so the player never leaves the ground, and ends on dry land, no water.
        var states = States(SceneLibrary.Load("water-walk"), "west-out-of-the-lake");
        Assert.All(states, s => Assert.True(s.Contact && s.OnWalkable));
        var last = states[^1];
        Assert.True(last.Position.Origin.X < 144f);
        Assert.Equal(0.005f, last.Position.Origin.Z, 1e-4f);
        Assert.False(last.ContactPlaneIsWater);
    }

    // ---- the scene format's terrain types ----------------------------------------------------------------

    private const string Land = """
        {
          "version": 1,
          "setups": { "player": { "spheres": [{ "center": [0, 0, 0.475], "radius": 0.48 }], "stepUpHeight": 0.6, "stepDownHeight": 0.04 } },
          "landblocks": [{ "id": "0xA9B4", "height": 0 }],
          "movers": [{ "name": "m", "setup": "player", "position": [100, 98, 0], "floorZ": 0, "motion": [[0, 0.1, 0]] }]
        }
        """;

    private static JsonObject Block(JsonObject doc) => doc["landblocks"]![0]!.AsObject();

    private static LandCell Cell(JsonObject doc, uint index) => (LandCell)SceneLoader.Load(doc.ToJsonString()).World.Cells.Get(0xA9B40000 | index)!;

    private static void Refused(JsonObject doc, string path, string detail)
    {
        var ex = Assert.Throws<SceneFormatException>(() => SceneLoader.Load(doc.ToJsonString()));
        Assert.Equal(path, ex.JsonPath);
        Assert.Contains(detail, ex.Message);
    }

    [Fact]
    public void ALandblockWithoutTerrainTypes_IsDry_AndOneTypeForEveryVertexFloodsIt()
    {
        var doc = JsonNode.Parse(Land)!.AsObject();
        Assert.Equal(WaterType.NotWater, Cell(doc, 1).WaterType);
        Block(doc)["terrainType"] = 16;   // WaterRunning
        Assert.Equal(WaterType.EntirelyWater, Cell(doc, 1).WaterType);
        Block(doc)["terrainType"] = 21;   // Reserved21: solid
        Assert.Equal(WaterType.NotWater, Cell(doc, 1).WaterType);
    }

    [Fact]
    public void TerrainTypes_AreIndexedLikeTheHeights()
    {
        // Vertex (1, 0) is index 1 * 9 + 0 = 9: the corner shared by cells (0, 0) and (1, 0) (ids 1 and 9).
        var doc = JsonNode.Parse(Land)!.AsObject();
        var types = Enumerable.Repeat(1, 81).Select(v => (JsonNode?)v).ToArray();
        types[9] = 20;
        Block(doc)["terrainTypes"] = new JsonArray(types);
        Assert.Equal(WaterType.PartiallyWater, Cell(doc, 1).WaterType);
        Assert.Equal(WaterType.PartiallyWater, Cell(doc, 9).WaterType);
        Assert.Equal(WaterType.NotWater, Cell(doc, 2).WaterType);
    }

    [Fact]
    public void BadTerrainTypes_AreRefused_NamingTheirPath()
    {
        var doc = JsonNode.Parse(Land)!.AsObject();
        Block(doc)["terrainType"] = 32;
        Refused(doc, "landblocks[0].terrainType", "a terrain type is 0..31, got 32");
        Block(doc)["terrainType"] = -1;
        Refused(doc, "landblocks[0].terrainType", "a terrain type is 0..31, got -1");
        Block(doc)["terrainTypes"] = new JsonArray(Enumerable.Repeat(1, 81).Select(v => (JsonNode?)v).ToArray());
        Refused(doc, "landblocks[0]", "at most one of \"terrainType\"");
        Block(doc).Remove("terrainType");
        Block(doc)["terrainTypes"] = new JsonArray(Enumerable.Repeat(1, 80).Select(v => (JsonNode?)v).ToArray());
        Refused(doc, "landblocks[0].terrainTypes", "expected 81 terrain types");
        var types = Enumerable.Repeat(1, 81).Select(v => (JsonNode?)v).ToArray();
        types[40] = 2.5;
        Block(doc)["terrainTypes"] = new JsonArray(types);
        Refused(doc, "landblocks[0].terrainTypes[40]", "expected an integer");
    }
}
